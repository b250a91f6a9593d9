/* Crushing model (plain C++): pi (M_PI is not standard C++) and the sphere volume. */
#ifndef CRUSH_CONSTANTS_H
#define CRUSH_CONSTANTS_H

namespace crush {

constexpr double pi = 3.141592653589793238462643383279502884;

// Volume (m^3) of a sphere of diameter d (m).
inline double sphere_volume(double d) { return pi / 6.0 * d * d * d; }

}  // namespace crush

#endif
