/* Plain-double wrapper of libcerf's C99-complex functions (see cerf_wrap.h). */
#include "seakeeping/green/cerf_wrap.h"

#include <cerf.h>
#include <complex.h>

void hullopt_cdawson(double xr, double xi, double* fr, double* fi) {
  const double _Complex f = cdawson(xr + xi * I);
  *fr = creal(f);
  *fi = cimag(f);
}

void hullopt_cerfc(double xr, double xi, double* fr, double* fi) {
  const double _Complex f = cerfc(xr + xi * I);
  *fr = creal(f);
  *fi = cimag(f);
}
