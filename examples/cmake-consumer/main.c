/* SPDX-License-Identifier: MIT */
/*
 * examples/cmake-consumer/main.c: the smallest use of libmdr, checked by
 * make cmake-check and make install-check on the host and the Cortex-M4F.
 * The JKR pull-off force of a paraboloid under fixed load against its
 * closed form F* = -(3/2) pi w R (seed 4.36). Exit status 0 when the f32
 * result is within 1e-6 of it (relative; measured 94e-9 on the host and on
 * the Cortex-M4F, within 11x). The message prints no floating-point value.
 */
#include <stdio.h>

#include "mdr.h"

int main(void)
{
    const float R = 20e-9f, E = 1e9f, w = 0.05f;
    const float p[3] = {R, 0.0f, 0.0f};
    const float ref = -1.5f * 3.14159265f * w * R;
    mdr_contact_f32 c;
    mdr_critstate_f32 cs;
    float a0, rel;
    if (mdr_contact_init_f32(&c, MDR_PROFILE_PARABOLOID, p, E, w) != MDR_OK ||
        mdr_default_start_f32(&c, &a0) != MDR_OK ||
        mdr_critical_f32(&c, MDR_CONTROL_LOAD, 1.0f, a0, &cs) != MDR_OK) {
        puts("consumer: libmdr returned an error");
        return 1;
    }
    rel = (cs.F - ref) / ref;
    if (rel < 0.0f)
        rel = -rel;
    if (!(rel < 1e-6f)) {
        printf("consumer: pull-off off by %d ppm of -(3/2) pi w R\n", (int)(rel * 1e6f));
        return 1;
    }
    printf("consumer: JKR pull-off within %d ppb of -(3/2) pi w R (%s)\n", (int)(rel * 1e9f),
           mdr_status_str(MDR_OK));
    return 0;
}
