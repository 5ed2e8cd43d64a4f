#pragma once
// Plain-double C interface to libcerf's complex functions (docs/theory.md, 'Complex error and Dawson
// functions (libcerf)'). libcerf 1.x declares C99 `double _Complex` functions, which C++ cannot call
// portably; this header and cerf_wrap.c hide that.
#ifdef __cplusplus
extern "C" {
#endif

/// Complex Dawson function F(x) = e^{−x²} ∫_0^x e^{u²} du at x = xr + i xi: F = *fr + i *fi.
void hullopt_cdawson(double xr, double xi, double* fr, double* fi);
/// Complementary error function erfc(x) at x = xr + i xi.
void hullopt_cerfc(double xr, double xi, double* fr, double* fi);

#ifdef __cplusplus
}
#endif
