// io/output_format.cpp: choosing an output format by name or by file extension, and
// writing a triangulation or a Voronoi diagram in it, all or nothing.
#include <cctype>
#include <ostream>
#include <string>

#include "drange/errors.hpp"
#include "drange/formats.hpp"
#include "drange/io.hpp"
#include "io/result_checks.hpp"

namespace drange {
namespace {

struct FormatName {
  const char* name;
  const char* extension;  // nullptr: chosen by name only
  OutputFormat format;
};

constexpr FormatName kFormats[] = {
    {"qhull", nullptr, OutputFormat::Qhull},
    {"json", ".json", OutputFormat::Json},
    {"npz", ".npz", OutputFormat::Npz},
    {"vtu", ".vtu", OutputFormat::Vtu},
    {"off", ".off", OutputFormat::Off},
};

std::string lowercase(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

bool ends_with(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

const char* output_format_names() { return "qhull, json, npz, vtu, off"; }

OutputFormat output_format_from_name(const std::string& name) {
  for (const FormatName& entry : kFormats) {
    if (name == entry.name) return entry.format;
  }
  throw UsageError("unknown output format '" + name + "' (expected one of: " + output_format_names() + ")");
}

OutputFormat output_format_from_path(const std::string& path, OutputFormat fallback) {
  const std::string lower = lowercase(path);
  for (const FormatName& entry : kFormats) {
    if (entry.extension != nullptr && ends_with(lower, entry.extension)) return entry.format;
  }
  return fallback;
}

void write_delaunay(const std::string& path, OutputFormat format, PointsView points,
                    const Triangulation& triangulation) {
  write_file_atomically(path, [&](std::ostream& out) {
    switch (format) {
      case OutputFormat::Qhull:
        write_index_rows(out, triangulation.simplices, triangulation.dim + 1);
        return;
      case OutputFormat::Json:
        write_delaunay_json(out, triangulation);
        return;
      case OutputFormat::Npz:
        write_delaunay_npz(out, triangulation);
        return;
      case OutputFormat::Vtu:
        write_delaunay_vtu(out, points, triangulation);
        return;
      case OutputFormat::Off:
        write_delaunay_off(out, points, triangulation);
        return;
    }
  });
}

void write_voronoi(const std::string& path, OutputFormat format, PointsView points, const Voronoi& diagram,
                   const ClippedCells* cells) {
  io::check_same_input(points, diagram.dim, diagram.num_points, "write_voronoi");
  if ((format == OutputFormat::Vtu || format == OutputFormat::Off) && cells == nullptr) {
    throw UsageError(std::string("write_voronoi: ") + (format == OutputFormat::Vtu ? "VTK" : "OFF") +
                     " output draws the Voronoi cells clipped to a box, and none were given (drange::clip_cells)");
  }
  write_file_atomically(path, [&](std::ostream& out) {
    switch (format) {
      case OutputFormat::Qhull:
        write_qvoronoi_o(out, diagram);
        return;
      case OutputFormat::Json:
        write_voronoi_json(out, diagram, cells);
        return;
      case OutputFormat::Npz:
        write_voronoi_npz(out, diagram, cells);
        return;
      case OutputFormat::Vtu:
        write_cells_vtu(out, diagram, *cells);
        return;
      case OutputFormat::Off:
        write_cells_off(out, *cells);
        return;
    }
  });
}

}  // namespace drange
