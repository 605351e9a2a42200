// io/write_npz.cpp: .npz archives, the multi-array format of numpy.savez: a zip archive with
// one .npy member per array, stored without compression. The zip layout follows PKWARE's
// APPNOTE.TXT (sections 4.3.7 local file header, 4.3.12 central directory header, 4.3.16
// end of central directory record); the checksum is the CRC-32 of ISO 3309 / ITU-T V.42.
//
// The output may be a pipe, so nothing is patched after the fact: each member's size and
// CRC are computed in a first pass over its data, then the member is written with its final
// local header. Archives of 4 GiB or more would need ZIP64, which is not written; they are
// refused before the first byte goes out.
#include <array>
#include <cstdint>
#include <ostream>
#include <set>
#include <string>
#include <vector>

#include "drange/errors.hpp"
#include "drange/formats.hpp"
#include "io/npy.hpp"
#include "io/result_checks.hpp"

namespace drange {
namespace {

constexpr std::uint32_t kLocalHeaderSignature = 0x04034b50;
constexpr std::uint32_t kCentralHeaderSignature = 0x02014b50;
constexpr std::uint32_t kEndOfDirectorySignature = 0x06054b50;
constexpr std::uint16_t kVersion = 20;            // "2.0": the version needed to extract, and made by (MS-DOS host)
constexpr std::uint16_t kStored = 0;              // compression method: none
constexpr std::uint16_t kDosTime = 0;             // 00:00:00
constexpr std::uint16_t kDosDate = (1 << 5) | 1;  // 1980-01-01, the earliest DOS date: reproducible archives
constexpr std::size_t kLocalHeaderBytes = 30;
constexpr std::size_t kCentralHeaderBytes = 46;
constexpr std::size_t kEndOfDirectoryBytes = 22;
constexpr std::uint64_t kZip32Limit = 0xffffffff;  // this value in a size or offset field means ZIP64
constexpr std::size_t kMaxMembers = 0xffff;

// CRC-32 with the reflected polynomial 0xEDB88320, one table lookup per byte.
class Crc32 {
 public:
  void update(const char* data, std::size_t n) {
    static const std::array<std::uint32_t, 256> table = make_table();
    for (std::size_t i = 0; i < n; ++i)
      state_ = table[(state_ ^ static_cast<unsigned char>(data[i])) & 0xff] ^ (state_ >> 8);
  }
  std::uint32_t value() const { return ~state_; }

 private:
  static std::array<std::uint32_t, 256> make_table() {
    std::array<std::uint32_t, 256> table{};
    for (std::uint32_t i = 0; i < 256; ++i) {
      std::uint32_t c = i;
      for (int bit = 0; bit < 8; ++bit) c = (c & 1) ? 0xedb88320 ^ (c >> 1) : c >> 1;
      table[i] = c;
    }
    return table;
  }
  std::uint32_t state_ = 0xffffffff;
};

// Little-endian fields of the zip headers.
void put16(std::string& out, std::uint64_t value) {
  for (int b = 0; b < 2; ++b) out += static_cast<char>((value >> (8 * b)) & 0xff);
}
void put32(std::string& out, std::uint64_t value) {
  for (int b = 0; b < 4; ++b) out += static_cast<char>((value >> (8 * b)) & 0xff);
}

// A member ready to be written: everything its headers need.
struct Entry {
  std::string file_name;  // "<name>.npy"
  std::string npy_header;
  const NpyArray* array;
  std::uint64_t size = 0;  // the whole .npy: header and data
  std::uint32_t crc = 0;
  std::uint64_t offset = 0;  // of its local header in the archive
};

// The fields that the local and the central header share, from "version needed" to the
// extra field length.
std::string common_fields(const Entry& entry) {
  std::string out;
  put16(out, kVersion);
  put16(out, 0);  // flags: sizes and CRC are in this header, the name is ASCII
  put16(out, kStored);
  put16(out, kDosTime);
  put16(out, kDosDate);
  put32(out, entry.crc);
  put32(out, entry.size);  // compressed size: stored, so the same
  put32(out, entry.size);
  put16(out, entry.file_name.size());
  put16(out, 0);  // no extra field
  return out;
}

std::string local_header(const Entry& entry) {
  std::string out;
  put32(out, kLocalHeaderSignature);
  return out + common_fields(entry) + entry.file_name;
}

std::string central_header(const Entry& entry) {
  std::string out;
  put32(out, kCentralHeaderSignature);
  put16(out, kVersion);  // made by
  out += common_fields(entry);
  put16(out, 0);  // comment length
  put16(out, 0);  // disk number
  put16(out, 0);  // internal attributes
  put32(out, 0);  // external attributes
  put32(out, entry.offset);
  return out + entry.file_name;
}

std::string end_of_directory(std::size_t entries, std::uint64_t directory_size, std::uint64_t directory_offset) {
  std::string out;
  put32(out, kEndOfDirectorySignature);
  put16(out, 0);  // this disk
  put16(out, 0);  // the disk where the directory starts
  put16(out, entries);
  put16(out, entries);
  put32(out, directory_size);
  put32(out, directory_offset);
  put16(out, 0);  // comment length
  return out;
}

// Sizes, CRCs and offsets of every member, and the checks that must pass before writing.
std::vector<Entry> prepare(const std::vector<NpzMember>& members, std::uint64_t& directory_offset,
                           std::uint64_t& directory_size) {
  if (members.size() >= kMaxMembers) {
    throw UsageError("write_npz: " + std::to_string(members.size()) +
                     " members need ZIP64, which drange does not write");
  }
  std::vector<Entry> entries;
  std::set<std::string> names;
  std::uint64_t offset = 0;
  directory_size = 0;
  for (const NpzMember& member : members) {
    if (member.name.empty() || !names.insert(member.name).second) {
      throw UsageError("write_npz: member name '" + member.name + "' is empty or repeated");
    }
    if (member.array.data == nullptr && member.array.size() != 0) {
      throw UsageError("write_npz: no data for the non-empty member '" + member.name + "'");
    }
    Entry entry{member.name + ".npy", io::npy_header(member.array), &member.array};
    entry.size = entry.npy_header.size() + io::npy_data_bytes(member.array);
    entry.offset = offset;
    offset += kLocalHeaderBytes + entry.file_name.size() + entry.size;
    directory_size += kCentralHeaderBytes + entry.file_name.size();
    entries.push_back(std::move(entry));
  }
  directory_offset = offset;
  const std::uint64_t total = directory_offset + directory_size + kEndOfDirectoryBytes;
  if (total >= kZip32Limit) {
    throw UsageError("write_npz: the archive would take " + std::to_string(total) +
                     " bytes; .npz files of 4 GiB or more need ZIP64, which drange does not write");
  }
  // The CRCs last: they read all the data, which is wasted if a check above fails.
  for (Entry& entry : entries) {
    Crc32 crc;
    crc.update(entry.npy_header.data(), entry.npy_header.size());
    io::for_each_npy_block(*entry.array, [&](const char* bytes, std::size_t n) { crc.update(bytes, n); });
    entry.crc = crc.value();
  }
  return entries;
}

void write_bytes(std::ostream& out, const std::string& bytes) {
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

// The member arrays of a ragged list: "<name>" the values, "<name>_offsets" the row starts.
void add_lists(std::vector<NpzMember>& members, const std::string& name, const IndexLists& lists) {
  members.push_back({name, NpyArray(lists.values.data(), {lists.values.size()})});
  members.push_back({name + "_offsets", NpyArray(lists.offsets.data(), {lists.offsets.size()})});
}

}  // namespace

void write_npz(std::ostream& out, const std::vector<NpzMember>& members) {
  std::uint64_t directory_offset = 0, directory_size = 0;
  const std::vector<Entry> entries = prepare(members, directory_offset, directory_size);
  for (const Entry& entry : entries) {
    write_bytes(out, local_header(entry));
    write_bytes(out, entry.npy_header);
    io::for_each_npy_block(
        *entry.array, [&](const char* bytes, std::size_t n) { out.write(bytes, static_cast<std::streamsize>(n)); });
  }
  for (const Entry& entry : entries) write_bytes(out, central_header(entry));
  write_bytes(out, end_of_directory(entries.size(), directory_size, directory_offset));
}

void write_delaunay_npz(std::ostream& out, const Triangulation& triangulation) {
  io::check_triangulation(triangulation, "write_delaunay_npz");
  const std::size_t width = static_cast<std::size_t>(triangulation.dim) + 1;
  const std::int64_t ndim = triangulation.dim;
  const auto npoints = static_cast<std::int64_t>(triangulation.num_points);
  std::vector<std::int32_t> coplanar;
  for (const Duplicate& duplicate : triangulation.duplicates) {
    coplanar.insert(coplanar.end(),
                    {static_cast<std::int32_t>(duplicate.index), -1, static_cast<std::int32_t>(duplicate.original)});
  }

  std::vector<NpzMember> members{
      {"ndim", NpyArray(&ndim, {})},
      {"npoints", NpyArray(&npoints, {})},
      {"simplices", NpyArray(triangulation.simplices.data(), {triangulation.size(), width})},
  };
  if (!triangulation.neighbors.empty()) {
    members.push_back({"neighbors", NpyArray(triangulation.neighbors.data(), {triangulation.size(), width})});
  }
  members.push_back({"coplanar", NpyArray(coplanar.data(), {triangulation.duplicates.size(), 3})});
  write_npz(out, members);
}

void write_voronoi_npz(std::ostream& out, const Voronoi& diagram, const ClippedCells* cells) {
  io::check_voronoi(diagram, "write_voronoi_npz");
  if (cells != nullptr) io::check_cells_of(diagram, *cells, "write_voronoi_npz");
  const std::size_t dim = static_cast<std::size_t>(diagram.dim);
  const std::int64_t ndim = diagram.dim;
  const auto npoints = static_cast<std::int64_t>(diagram.num_points);

  std::vector<NpzMember> members{
      {"ndim", NpyArray(&ndim, {})},
      {"npoints", NpyArray(&npoints, {})},
      {"vertices", NpyArray(diagram.vertices.data(), {diagram.num_vertices(), dim})},
      {"ridge_points", NpyArray(diagram.ridge_points.data(), {diagram.num_ridges(), 2})},
  };
  add_lists(members, "ridge_vertices", diagram.ridge_vertices);
  add_lists(members, "regions", diagram.regions);
  members.push_back({"point_region", NpyArray(diagram.point_region.data(), {diagram.point_region.size()})});
  if (!diagram.volumes.empty())
    members.push_back({"volumes", NpyArray(diagram.volumes.data(), {diagram.volumes.size()})});
  if (cells != nullptr) {
    const std::size_t cell_dim = static_cast<std::size_t>(cells->dim);
    members.push_back({"clipped_box_lower", NpyArray(cells->box.lower.data(), {cells->box.lower.size()})});
    members.push_back({"clipped_box_upper", NpyArray(cells->box.upper.data(), {cells->box.upper.size()})});
    members.push_back({"clipped_points", NpyArray(cells->points.data(), {cells->points.size() / cell_dim, cell_dim})});
    add_lists(members, "clipped_faces", cells->faces);
    members.push_back({"clipped_cell_faces", NpyArray(cells->cell_faces.data(), {cells->cell_faces.size()})});
    members.push_back({"clipped_volumes", NpyArray(cells->volumes.data(), {cells->volumes.size()})});
  }
  write_npz(out, members);
}

}  // namespace drange
