// drange/drange.hpp: the whole public API.
#pragma once

#include "drange/check.hpp"
#include "drange/delaunay.hpp"
#include "drange/errors.hpp"
#include "drange/generate.hpp"
#include "drange/io.hpp"
#include "drange/points.hpp"
