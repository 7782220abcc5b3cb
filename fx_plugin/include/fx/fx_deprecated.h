/* CubeFx C API: the output structs of API 2.0, which carry no size and never grow; only the
 * deprecated entries of fxApi write them (their sized successors, fxStats2 and the rest, are in
 * fx/fx.h). Included by fx/fx.h after fx_constants.h; include fx/fx.h. */
#ifndef FX_FX_DEPRECATED_H
#define FX_FX_DEPRECATED_H

#include <stdint.h>

#include "fx_constants.h"

/* Deprecated (API 2.0, no size, never to grow): the same fields as their ...2 structs above,
 * written whole by the 2.0 entries. */
typedef struct fxStats {
    int reactions, particlesAlive, particleCapacity, particlesDrawn, reloads, reloadErrors, apiErrors;
} fxStats;
typedef struct fxParticleCheck { int alive, capacity, nonFinite; } fxParticleCheck;
typedef struct fxReactionStats {
    char name[72];        /* "" for a bad index */
    char technique[16];
    int alive;
    uint64_t emitted, dropped;
} fxReactionStats;
typedef struct fxReactionKeyInfo {
    const char* key;
    int kind;
    double min, max;
    const char* const* choices;
    int choiceCount;
    const char* unit;
    const char* help;
} fxReactionKeyInfo;
typedef struct fxSmokeShadow {
    uint32_t opacity;
    float worldToShadow[16];
} fxSmokeShadow;
/* Deprecated, with no successor: nothing is counted since API 2.1 (and fade classification has
 * no effect since 2.4). */
typedef struct fxFadeClassCounts { int fadeNeeded, inFront, hidden; fxBool counted; } fxFadeClassCounts;

#endif /* FX_FX_DEPRECATED_H */
