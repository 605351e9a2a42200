// delaunay/shell/shell_arithmetic.hpp: a candidate's lifted in-sphere form about the centre g
// of a shell's sphere, b . (x - g) + lift (|x - g|^2 - rho) + constant, computed in floating
// point with a proven bound of each coefficient's error (float_form; the exact form is
// geometry::exact_lifted_form).
//
// Why about g: near the sphere the search's own form has terms far larger than its value, so
// its tests there would mostly go to GMP. About g and rho, and from the points' offsets
// (SphereShell::offset), the form's terms are small: the points' tests resolve their sign to
// within rounding of those small terms, GMP is left with the true ties, and the bounds are
// tight enough for the search to prune whole nodes with them (search/shell_pruner.hpp, node_prunes).
// The form is computed once per candidate; from 4D, its minors of the facet's rows once per
// facet (FacetMinors).
#pragma once

namespace drange::engine {

// One sphere of the shell: its centre g (dim doubles), the squared radius rho its offsets are
// taken from, and their error bound eta.
struct ShellSphere {
  const double* centre;
  double rho;
  double eta;
};

// The lifted determinant det[r_1; ...; r_d; r_x] (rows relative to f0, as in
// geometry::exact_lifted_form) as b . (x - g) + lift (|x - g|^2 - rho) + constant, computed in
// floating point from the points' offsets, with bounds of each coefficient's distance to the
// exact one: for d = 2 to 8. `rows` are the d points after f0, `s0` and `row_offsets` their
// offsets (SphereShell::offset). False when a bound is not small against its terms (a
// near-flat simplex, or points exactly on the fitted sphere, where b is 0) or a value is too
// large; the caller also watches the floating-point flags (an underflow voids the bounds).
constexpr int kFloatFormMaxDim = 8;
struct FloatForm {
  double b[kFloatFormMaxDim], b_err[kFloatFormMaxDim];
  double lift, lift_err, constant, constant_err;
  double b_err_sum;  // sum of b_err
};
// From 4D, the form's cofactors are expanded along the candidate's row (rows[d - 1]), over
// minors of the facet's rows alone: those are the same for every candidate of a facet, and
// `minors`, when given, keeps them from the first call (ready) until the caller resets it for
// another facet. Without it they are computed for this call only; the form is the same.
struct FacetMinors {
  static constexpr int kPairs = kFloatFormMaxDim * (kFloatFormMaxDim - 1) / 2;
  bool ready = false;
  double sub[kFloatFormMaxDim - 1][kPairs][2];  // facet rows but i, columns but a pair: value, tree
  double top[kFloatFormMaxDim][2];              // all the facet rows, columns but c: value, tree
};
bool float_form(const ShellSphere& sphere, int d, const double* f0, double s0, const double* const* rows, const double* row_offsets,
                FloatForm& form, FacetMinors* minors = nullptr);

}  // namespace drange::engine
