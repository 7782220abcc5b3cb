/* What the era hosts (C89Host.c, Api20Host.c) share: the failed-check count that is their exit
 * status, CHECK, and the car they both drive. C89 (no // comments, no inline), and it includes
 * no fx header itself: include it after the fx header of the host's era (fx/fx.h or the frozen
 * fx_api_2_0.h), whose fxWheelContact it fills. */
#ifndef ERA_HOST_H
#define ERA_HOST_H

#include <stdio.h>
#include <string.h>

static int g_failed = 0;
/* Counts a failed check and prints its line; the host goes on (its exit status is g_failed). */
#define CHECK(cond)                                                                  \
    do {                                                                             \
        if (!(cond)) {                                                               \
            ++g_failed;                                                              \
            fprintf(stderr, "%s:%d: check failed: %s\n", __FILE__, __LINE__, #cond); \
        }                                                                            \
    } while (0)

static int hostWheelCount(void* user) {
    (void)user;
    return 4;
}

/* A car at the origin facing -Z in a standing burnout: the rear wheels (index 2, 3) spin on
 * asphalt. */
static void hostWheel(void* user, int index, fxWheelContact* out) {
    (void)user;
    memset(out, 0, sizeof *out);
    out->position[0] = (index & 1) ? 0.8f : -0.8f;
    out->position[2] = (index >= 2) ? 1.3f : -1.3f;
    out->rear = index >= 2;
    out->slip = out->rear ? 1.0f : 0.0f;
    out->grounded = 1;
    out->surface = FX_SURFACE_ASPHALT;
}

#endif
