// voronoi/stream_cells.cpp: drange::stream_clipped_cells, the clipped cells batch by batch from
// the points' Delaunay stars.
//
// A batch is a range of consecutive engine ids (the kd-tree's order, so its points are close
// together and their stars overlap). Its stars come from engine::StarWrapper: every simplex
// incident to a point of the batch, each once. A point's Delaunay neighbours (the other vertices
// of its star) include every point whose cell shares a (d-1)-face with its own, so cutting the
// box by their bisectors gives its clipped cell (cell_clipper.hpp). The simplices shared with
// the next batch are found again there: the price of holding only a batch.
//
// Threads take batches in increasing order, each with its own FacetSearch, StarWrapper and
// clipper over the shared read-only PointStore. A thread does not start batch b before batch
// b - window has been written, so at most `window` batches' texts wait in memory; the thread
// that hands over the batch next in line writes it and every following one that is ready.
// Each cell is formatted as soon as it is clipped, so only its text outlives it.
#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "delaunay/facet_search.hpp"
#include "delaunay/first_facet.hpp"
#include "delaunay/local_star.hpp"
#include "delaunay/prepare_points.hpp"
#include "delaunay/search_options.hpp"
#include "delaunay/team.hpp"
#include "drange/errors.hpp"
#include "drange/voronoi.hpp"
#include "voronoi/cell_clipper.hpp"

namespace drange {
namespace {

// Points per batch: at least kMinBatch, so that the simplices found twice (those reaching into
// the next batch) stay a small part of the work, and at least 1/kMaxBatches of the points,
// because each StarWrapper::stars call sets up marks for every point.
constexpr std::size_t kMinBatch = 16384;
constexpr std::size_t kMaxBatches = 256;
// Batches computed ahead of the one being written, per thread.
constexpr std::size_t kWindowPerThread = 2;

// Hands the batches' texts to `write` in batch order, holding at most `window` of them.
class OrderedWriter {
 public:
  OrderedWriter(std::size_t window, const std::function<void(const std::string&)>& write)
      : window_(window), ready_(window), write_(write) {}

  // Waits until batch `index` may be computed; false once stopped.
  bool wait_turn(std::size_t index) {
    std::unique_lock<std::mutex> lock(mutex_);
    turn_.wait(lock, [&] { return stopped_ || index < written_ + window_; });
    return !stopped_;
  }

  // Takes the text of batch `index`; writes it and the batches after it that are ready when it
  // is next in line and no other thread is writing (that one goes on with them).
  void deliver(std::size_t index, std::string text) {
    std::unique_lock<std::mutex> lock(mutex_);
    ready_[index % window_] = std::move(text);
    if (writing_) return;
    writing_ = true;
    while (!stopped_ && ready_[written_ % window_]) {
      const std::string next = std::move(*ready_[written_ % window_]);
      ready_[written_ % window_].reset();
      lock.unlock();
      write_(next);
      lock.lock();
      ++written_;
      turn_.notify_all();
    }
    writing_ = false;
  }

  void stop() {
    const std::lock_guard<std::mutex> lock(mutex_);
    stopped_ = true;
    turn_.notify_all();
  }

 private:
  const std::size_t window_;
  std::mutex mutex_;
  std::condition_variable turn_;
  std::size_t written_ = 0;  // batches written so far
  bool writing_ = false;
  bool stopped_ = false;
  std::vector<std::optional<std::string>> ready_;  // batch b at b % window
  const std::function<void(const std::string&)>& write_;
};

void clear_cells(ClippedCells& cells) {
  cells.points.clear();
  cells.faces.offsets.assign(1, 0);
  cells.faces.values.clear();
  cells.cell_faces.assign(1, 0);
  cells.volumes.clear();
}

// One thread's tools and scratch space.
class BatchWorker {
 public:
  BatchWorker(PointsView input, const Box& box, const engine::PointStore& points, const engine::SearchOptions& options,
              const engine::FirstFacet& first)
      : points_(points),
        search_(points, options),
        wrapper_(points, search_, first),
        clipper_(input, box),
        seen_(static_cast<std::size_t>(points.size), -1) {
    cell_.dim = input.dim;
    cell_.box = box;
  }

  // The text of the cells of engine ids [begin, end).
  template <class Format>
  std::string cells(std::int32_t begin, std::int32_t end, const Format& format) {
    const auto width = static_cast<std::size_t>(points_.dim + 1);
    const auto count = static_cast<std::size_t>(end - begin);
    wanted_.resize(count);
    for (std::size_t i = 0; i < count; ++i) wanted_[i] = begin + static_cast<std::int32_t>(i);
    rows_.clear();
    hull_.clear();
    wrapper_.stars(wanted_, rows_, counters_, hull_);
    star_simplices_ += rows_.size() / width;

    // Each batch point's simplices, grouped by point (a counting sort):
    // incident_[offsets_[i] .. offsets_[i+1]) are the rows holding the batch's point i.
    const auto in_batch = [&](std::int32_t v) { return v >= begin && v < end; };
    offsets_.assign(count + 1, 0);
    for (const std::int32_t v : rows_)
      if (in_batch(v)) ++offsets_[static_cast<std::size_t>(v - begin) + 1];
    for (std::size_t i = 0; i < count; ++i) offsets_[i + 1] += offsets_[i];
    incident_.resize(offsets_[count]);
    next_.assign(offsets_.begin(), offsets_.end() - 1);
    for (std::size_t at = 0; at < rows_.size(); ++at)
      if (in_batch(rows_[at]))
        incident_[next_[static_cast<std::size_t>(rows_[at] - begin)]++] = static_cast<std::int32_t>(at / width);

    std::string text;
    for (std::size_t i = 0; i < count; ++i) {
      const auto p = static_cast<std::int32_t>(begin + static_cast<std::int32_t>(i));
      // Each neighbour once (seen_[v] == p: v is already a partner of p), as an input index.
      partners_.clear();
      seen_[static_cast<std::size_t>(p)] = p;
      for (std::size_t k = offsets_[i]; k < offsets_[i + 1]; ++k)
        for (std::size_t a = 0; a < width; ++a) {
          const std::int32_t v = rows_[static_cast<std::size_t>(incident_[k]) * width + a];
          if (seen_[static_cast<std::size_t>(v)] == p) continue;
          seen_[static_cast<std::size_t>(v)] = p;
          partners_.push_back(points_.input_index[static_cast<std::size_t>(v)]);
        }
      const std::int32_t id = points_.input_index[static_cast<std::size_t>(p)];
      clear_cells(cell_);
      clipper_.append(static_cast<std::size_t>(id), partners_.data(), partners_.size(), cell_);
      format(cell_, id, text);
    }
    return text;
  }

  std::size_t star_simplices() const { return star_simplices_; }

 private:
  const engine::PointStore& points_;
  engine::FacetSearch search_;
  engine::StarWrapper wrapper_;
  cells::CellClipper clipper_;
  engine::SearchCounters counters_;
  std::vector<std::int32_t> wanted_, rows_, hull_, incident_, partners_;
  std::vector<std::size_t> offsets_, next_;
  std::vector<std::int32_t> seen_;  // by engine id: the last point that took it as a partner
  std::size_t star_simplices_ = 0;
  ClippedCells cell_;  // the cell being clipped
};

}  // namespace

CellStreamReport stream_clipped_cells(PointsView input, const Box& box, const Options& options,
                                      const std::function<void(const ClippedCells&, std::int32_t, std::string&)>& format,
                                      const std::function<void(const std::string&)>& write) {
  if (input.dim != 2 && input.dim != 3)
    throw UsageError("clipped cells are computed in 2D and 3D; the points have dimension " + std::to_string(input.dim));
  cells::check_box(box, input.dim);
  const engine::SearchOptions search_options = engine::search_variant(options.variant);
  if (options.algorithm != "auto" && options.algorithm != "direct" && options.algorithm != "incremental")
    throw UsageError("unknown algorithm '" + options.algorithm + "' (expected one of: " + algorithm_names() + ")");
  if (options.threads < 0)
    throw UsageError("threads must be 0 (all hardware threads) or a positive count, got " + std::to_string(options.threads));

  CellStreamReport report;
  engine::Team team(engine::resolve_threads(options.threads));
  const engine::PointStore points =
      engine::prepare_points(input, engine::search_leaf_size(input.dim), report.duplicates, team, search_options);
  const engine::FirstFacet first = engine::find_first_facet(points, team);

  const auto n = static_cast<std::size_t>(points.size);
  const std::size_t batch_size = std::max(kMinBatch, (n + kMaxBatches - 1) / kMaxBatches);
  const std::size_t batches = (n + batch_size - 1) / batch_size;
  const int threads = static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(team.threads()), batches));
  OrderedWriter writer(kWindowPerThread * static_cast<std::size_t>(threads), write);
  std::atomic<std::size_t> next_batch{0}, star_simplices{0};
  team.run(
      threads,
      [&](int) {
        BatchWorker worker(input, box, points, search_options, first);
        for (std::size_t b; (b = next_batch.fetch_add(1)) < batches && writer.wait_turn(b);) {
          const auto begin = static_cast<std::int32_t>(b * batch_size);
          const auto end = static_cast<std::int32_t>(std::min(n, (b + 1) * batch_size));
          writer.deliver(b, worker.cells(begin, end, format));
        }
        star_simplices += worker.star_simplices();
      },
      [&] { writer.stop(); });
  report.cells = n;
  report.star_simplices = star_simplices.load();
  report.batches = batches;
  report.threads = static_cast<std::size_t>(threads);
  return report;
}

}  // namespace drange
