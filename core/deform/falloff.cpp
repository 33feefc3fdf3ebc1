#include "core/deform/falloff.h"

namespace trimlab::deform {

double falloff(FalloffProfile profile, double t)
{
    if (!(t < 1.0))
        return 0.0; // also NaN
    if (t < 0.0)
        t = 0.0;
    const double s = 1.0 - t;
    switch (profile) {
    case FalloffProfile::Smooth: {
        const double bell = 1.0 - t * t;
        return bell * bell;
    }
    case FalloffProfile::Linear:
        return s;
    case FalloffProfile::Sharp:
        return s * s * s;
    }
    return 0.0;
}

} // namespace trimlab::deform
