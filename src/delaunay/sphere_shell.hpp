// delaunay/sphere_shell.hpp: the sphere shell, the search's shortcut for points that lie near
// a sphere, near concentric spheres, or near spheres about several centres (bubbles, the
// cells of a foam) (our step, SearchOptions::sphere_shell). The one header the search and the
// point preparation include for it; its three parts live in delaunay/shell/.
//
// Why: on (nearly) cospherical input, every candidate's sphere is within rounding of the input
// sphere, so its ball meets every kd-tree node near that sphere and the search scans nearly
// all the points, for every facet: quadratic work. But the search's test, sigma I(p, x), is
// linear in (x, |x - g|^2) for any fixed g; with g the input sphere's centre, a node's points
// have |x - g|^2 in a range as thin as their distance from that sphere, and the form's least
// value over the node proves, for many nodes, that none of their points beats the candidate.
// Only the points within rounding of the candidate's sphere are then tested.
//
// The parts:
// - shell/sphere_fit.hpp: finding the spheres the points lie near. The bounds are sound for
//   any g, but useful only when most points lie near a sphere, near concentric spheres, or
//   (patch by patch) near spheres about several centres, so the shell is built only then.
// - shell/shell_index.hpp: SphereShell, per point its sphere and its offset |x - g|^2 - rho,
//   per kd-tree node the range of those offsets and a cone from g over its points, per leaf
//   its points in blocks by offset; fit_sphere_shell fits the spheres and builds it.
// - shell/shell_arithmetic.hpp: a candidate's lifted form about a sphere's centre, in floating
//   point with a bound of each coefficient's error (float_form).
// The shell changes which nodes are visited, never the point found.
#pragma once

#include "delaunay/shell/shell_arithmetic.hpp"
#include "delaunay/shell/shell_index.hpp"
