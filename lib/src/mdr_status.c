/* mdr_status.c: names of the status codes (shared by every arithmetic). */
#include "mdr_types.h"

const char *mdr_status_str(mdr_status s)
{
    switch (s) {
    case MDR_OK: return "ok";
    case MDR_E_NULL: return "null pointer";
    case MDR_E_NONFINITE: return "input is NaN or infinite";
    case MDR_E_PARAM: return "parameter out of range";
    case MDR_E_KIND: return "unknown profile kind";
    case MDR_E_RADIUS: return "contact radius outside the profile's domain";
    case MDR_E_POSITION: return "radial position outside [0, a)";
    case MDR_E_CONTROL: return "unknown control mode or machine stiffness not > 0";
    case MDR_E_NOCONV: return "iteration cap reached";
    case MDR_E_SINGULAR: return "quantity is singular at this point";
    case MDR_E_OVERFLOW: return "result overflows the arithmetic";
    default: return "unknown status";
    }
}
