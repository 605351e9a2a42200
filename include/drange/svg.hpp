// drange/svg.hpp: SVG pictures of 2D results, made to show at a glance whether a
// triangulation and its Voronoi diagram are right: equal scales on both axes (so Voronoi
// edges visibly cross their Delaunay edges at right angles), y pointing up, the convex hull
// emphasised, and the counts in a legend.
#pragma once

#include <iosfwd>
#include <string>

#include "drange/delaunay.hpp"
#include "drange/points.hpp"
#include "drange/voronoi.hpp"

namespace drange {

struct SvgOptions {
  bool triangulation = true;   // the Delaunay edges, the convex hull's thicker
  bool voronoi = true;         // the Voronoi edges, dashed (needs a diagram)
  bool circumcircles = false;  // the circumcircle of every triangle, light
  bool points = true;          // a dot per input point, drawn on top
  bool point_labels = false;   // each point's input index next to it: for small inputs only
  double width_px = 800;       // the picture's width; its height follows from the view's aspect
  double margin = 0.05;        // space around the points' bounding box, a fraction of its larger side
  std::string title;           // the <title>; empty: a description with the number of points
};

// Writes an SVG picture of the 2D triangulation `t` of `points` and, when `diagram` is not
// null, of its Voronoi diagram (`diagram` may be null: the triangulation alone is drawn).
// The view is the points' bounding box plus the margin, with equal scales, y up (a view
// thinner than 1:4 is widened to that), and a 30 px band below it holds the legend. Voronoi
// edges and circumcircles are clipped to the view; an unbounded Voronoi edge is drawn as a
// ray from its finite vertex out of the view, away from the hull, which relies on the
// triangles being positively oriented, as drange::delaunay writes them. Each layer is one
// <g> (ids "circles", "delaunay", "voronoi", "hull", "points", "labels", "legend") holding one
// <path> (the labels: one <text> per point), so that 100 000 points with their Voronoi
// diagram take about 9.5 MB.
// Throws UsageError when the points are not 2D ("SVG pictures are 2D only, the points have
// dimension d"), or when `t` or `diagram` do not match the points (dimension, indices).
void write_svg(std::ostream& out, PointsView points, const Triangulation& t, const Voronoi* diagram,
               const SvgOptions& options = {});

}  // namespace drange
