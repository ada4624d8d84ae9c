#include "querymodify/orientation.hpp"

#include <cmath>
#include <limits>

#include <gmpxx.h>

namespace dartcheck::querymodify {

namespace {

struct Terms {
  double det, permanent;
};

// Shewchuk's orient3d expansion about d, and the permanent that bounds its
// rounding error.
Terms orient3d(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  const double adx = a[0] - d[0], bdx = b[0] - d[0], cdx = c[0] - d[0];
  const double ady = a[1] - d[1], bdy = b[1] - d[1], cdy = c[1] - d[1];
  const double adz = a[2] - d[2], bdz = b[2] - d[2], cdz = c[2] - d[2];
  const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
  const double cdxady = cdx * ady, adxcdy = adx * cdy;
  const double adxbdy = adx * bdy, bdxady = bdx * ady;
  const double det = adz * (bdxcdy - cdxbdy) + bdz * (cdxady - adxcdy) + cdz * (adxbdy - bdxady);
  const double permanent = (std::fabs(bdxcdy) + std::fabs(cdxbdy)) * std::fabs(adz) + (std::fabs(cdxady) + std::fabs(adxcdy)) * std::fabs(bdz) +
                           (std::fabs(adxbdy) + std::fabs(bdxady)) * std::fabs(cdz);
  return {det, permanent};
}

int exact_sign(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  // mpq_class(double) is exact, and so is every operation below.
  mpq_class ad[3], bd[3], cd[3];
  for (int k = 0; k < 3; ++k) {
    ad[k] = mpq_class(a[static_cast<std::size_t>(k)]) - mpq_class(d[static_cast<std::size_t>(k)]);
    bd[k] = mpq_class(b[static_cast<std::size_t>(k)]) - mpq_class(d[static_cast<std::size_t>(k)]);
    cd[k] = mpq_class(c[static_cast<std::size_t>(k)]) - mpq_class(d[static_cast<std::size_t>(k)]);
  }
  const mpq_class det = ad[2] * (bd[0] * cd[1] - cd[0] * bd[1]) + bd[2] * (cd[0] * ad[1] - ad[0] * cd[1]) + cd[2] * (ad[0] * bd[1] - bd[0] * ad[1]);
  return sgn(det);
}

}  // namespace

const char* exact_arithmetic_version() { return ::gmp_version; }

double orientation_estimate(const Point3& a, const Point3& b, const Point3& c, const Point3& d) { return orient3d(a, b, c, d).det; }

int orientation_sign(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  // Shewchuk 1997, o3derrboundA = (7 + 56 eps) eps with eps = 2^-53: when
  // |det| exceeds it times the permanent, det has the exact sign. Also
  // exact when the products under- or overflow the bound's assumptions.
  constexpr double eps = std::numeric_limits<double>::epsilon() / 2;
  constexpr double bound = (7.0 + 56.0 * eps) * eps;
  // GMP traps on infinities and NaN: a non-finite point orients nothing.
  for (const Point3* p : {&a, &b, &c, &d})
    if (!std::isfinite((*p)[0]) || !std::isfinite((*p)[1]) || !std::isfinite((*p)[2])) return 0;
  const Terms t = orient3d(a, b, c, d);
  const double err = bound * t.permanent;
  if (std::isfinite(t.det) && std::isfinite(err) && t.permanent >= std::numeric_limits<double>::min() / eps) {
    if (t.det > err) return 1;
    if (-t.det > err) return -1;
  }
  return exact_sign(a, b, c, d);
}

}  // namespace dartcheck::querymodify
