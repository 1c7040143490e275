/*
** siteflip_internal.h: what siteflip.c shares with sitecensus.c (not
** installed).
*/
#ifndef FLIPLAB_SITEFLIP_INTERNAL_H
#define FLIPLAB_SITEFLIP_INTERNAL_H

#include "siteflip.h"

/* Relative gap between the worst sink's total and the GOT's, from their
** keys under joint j for a measure of sign s: (tw - tg) / max(|tw|, |tg|),
** 0 when tw <= tg or both are 0. */
double siteflip_gap(joint_id j, int s, double best_key, double worst_key);

#endif
