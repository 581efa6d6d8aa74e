/* SPDX-License-Identifier: MIT */
/* mdr_status.c: names of the status codes (shared by every arithmetic). */
#include "mdr_types.h"
#include "mdr_engine.h"
#include "mdr_fit.h"

const char *mdr_status_str(mdr_status s)
{
    switch (s) {
    case MDR_OK: return "ok";
    case MDR_E_NULL: return "null pointer";
    case MDR_E_NONFINITE: return "input is NaN or infinite";
    case MDR_E_PARAM: return "parameter out of range";
    case MDR_E_KIND: return "unknown profile kind, or one this function does not take (a scene: paraboloid, cone, power law of integer n)";
    case MDR_E_RADIUS: return "contact radius outside the profile's domain";
    case MDR_E_POSITION: return "radial position outside [0, a)";
    case MDR_E_CONTROL: return "unknown control mode, or machine stiffness not > 0 or out of range";
    case MDR_E_NOCONV: return "iteration cap reached";
    case MDR_E_SINGULAR: return "quantity is singular at this point";
    case MDR_E_OVERFLOW: return "result beyond the arithmetic's range (too large, or too small to keep its digits: a table too small, or a scene's contact too small against its units)";
    case MDR_E_OUTSIDE: return "contact edge beyond the last spring of the table";
    case MDR_E_TABLE: return "tabulated profile unusable (r not from 0 or not increasing, too few points, or g(0) not 0)";
    case MDR_E_SIZE: return "number of springs out of range";
    case MDR_E_DISABLED: return "removed from this build (mdr_options.h)";
    case MDR_E_FEW: return "too few points in the retract or in contact";
    case MDR_E_ORDER: return "samples not in time order: z not monotonic within the retract (or approach), rising to the end, or the pull-off above the approach's first touch (a curve read backwards)";
    case MDR_E_NOCONTACT: return "no contact in the curve";
    case MDR_E_NOPULLOFF: return "the curve never separates (no pull-off jump to the baseline)";
    case MDR_E_FITCAP: return "fit iteration cap reached";
    case MDR_E_DEGENERATE: return "the data do not determine the parameters";
    case MDR_E_JUMPS: return "the retract jumps before the pull-off (one-branch model does not apply)";
    case MDR_E_PINNED: return "the retract is straight to its pull-off: pinned to its rupture, or a pinned top its noise may hide (fit with the approach, or state unpinned)";
    case MDR_E_MISFIT: return "the fitted model does not reproduce the curve (residuals beyond its noise, overall, at the pull-off or in the free part next to it: a long-range tail, or a force lagging the jump, a detector filter or ringing): a poor first guess, units not SI, or a curve the model does not describe (a pull-off that is no fold: an approach read backwards)";
    default: return "unknown status";
    }
}

const char *mdr_event_str(uint8_t event)
{
    switch (event) {
    case MDR_EV_NONE: return "none";
    case MDR_EV_CONTACT: return "contact";
    case MDR_EV_JUMP_IN: return "jump-in";
    case MDR_EV_JUMP: return "jump";
    case MDR_EV_PULL_OFF: return "pull-off";
    case MDR_EV_RECONTACT: return "re-contact";
    case MDR_EV_SEPARATION: return "separation";
    default: return "unknown event";
    }
}

#if MDR_CFG_FIT
const char *mdr_regime_str(uint8_t regime)
{
    switch (regime) {
    case MDR_REGIME_JKR: return "JKR";
    case MDR_REGIME_TRANSITION: return "transition";
    case MDR_REGIME_DMT: return "DMT";
    default: return "none";
    }
}
#endif
