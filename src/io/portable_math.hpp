// io/portable_math.hpp: log and exp evaluated with + - * / and exact scalings only.
//
// The generators promise the same points on every machine. IEEE 754 makes + - * / and sqrt
// exactly reproducible, but the C library's log and exp differ in the last bit between
// implementations (glibc, musl, macOS, MSVC). These versions are accurate to a few ulps,
// which is all a random sampler needs, and give the same bits everywhere (compiled without
// -ffast-math and without fused multiply-add contraction, as the library is).
#pragma once

namespace drange::io {

// Natural logarithm of a finite x > 0.
double portable_log(double x);

// e^x for finite x (underflows to 0 and overflows to infinity like exp).
double portable_exp(double x);

}  // namespace drange::io
