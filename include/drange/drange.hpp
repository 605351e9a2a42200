// drange/drange.hpp: the whole public API.
#pragma once

#include "drange/check.hpp"
#include "drange/delaunay.hpp"
#include "drange/errors.hpp"
#include "drange/formats.hpp"
#include "drange/hull.hpp"
#include "drange/incremental.hpp"
#include "drange/generate.hpp"
#include "drange/io.hpp"
#include "drange/locate.hpp"
#include "drange/points.hpp"
#include "drange/svg.hpp"
#include "drange/voronoi.hpp"
