#pragma once
// A pool of worker threads that build terrain tiles (buildTile, a pure function of the shared,
// immutable Heightfield and the key). Workers touch nothing but their own queue state and the
// tiles they build; the caller (the render thread) takes finished tiles and owns the cache.
// Each key is built at most once while it is queued, in flight or finished but not yet taken.
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <span>
#include <thread>
#include <unordered_map>
#include <vector>

#include "terrain/Heightfield.hpp"
#include "terrain/Tile.hpp"

namespace og::terrain {

class TileBuilder {
 public:
  /// Most background requests kept queued: the latest frame's first (coarsest) ones.
  static constexpr std::size_t kMaxQueued = 512;

  using BuildFn = std::function<Tile(const TileKey&)>;

  /// buildTile on `heights` (kept alive by the pool). `workers` <= 0:
  /// std::thread::hardware_concurrency() (at least 1).
  explicit TileBuilder(std::shared_ptr<const Heightfield> heights, int workers = 0);
  /// Any thread-safe build function (tests).
  explicit TileBuilder(BuildFn build, int workers = 0);
  /// Stops and joins the workers; a tile in flight is finished first, then dropped.
  ~TileBuilder();
  TileBuilder(const TileBuilder&) = delete;
  TileBuilder& operator=(const TileBuilder&) = delete;

  /// Builds these keys (in parallel) and blocks until every one of them is finished (keys
  /// already queued or in flight are not built twice). Take them with takeFinished().
  void build(std::span<const TileKey> keys);
  /// Background requests, in priority order: replace the previous ones still queued (stale
  /// requests are dropped); keys in flight or finished are not queued again. At most kMaxQueued.
  void request(std::span<const TileKey> keys);

  struct Finished {
    std::vector<Tile> tiles;
    std::exception_ptr error;  ///< the first exception a worker threw since the last take
  };
  /// Tiles finished since the last call (never blocks).
  Finished takeFinished();

  /// Tiles queued, in flight or finished but not taken.
  [[nodiscard]] std::size_t pending() const;
  /// Blocks until nothing is queued or in flight (tests, benchmarks).
  void waitIdle();
  [[nodiscard]] int workerCount() const { return static_cast<int>(workers_.size()); }

 private:
  enum class State : std::uint8_t { Queued, Urgent, InFlight, Done };
  struct Entry {
    State state = State::Queued;
    bool blocking = false;  // a build() call waits for it
  };

  void work(const std::stop_token& stop);

  BuildFn build_;
  mutable std::mutex mutex_;
  std::condition_variable_any workCv_;  // work arrived (or stop requested)
  std::condition_variable doneCv_;      // a tile finished
  std::unordered_map<std::uint64_t, Entry> state_;  // every key queued, in flight or finished
  std::deque<TileKey> urgent_;   // blocking builds, before any request
  std::deque<TileKey> queued_;   // background requests (entries no longer Queued are skipped)
  std::size_t queuedCount_ = 0;  // entries of queued_ still in State::Queued
  std::size_t inFlight_ = 0;
  std::size_t blockingLeft_ = 0;  // keys build() still waits for
  std::vector<Tile> done_;
  std::exception_ptr error_;
  // Last member: destroyed first, so the threads are joined before the state they use dies.
  std::vector<std::jthread> workers_;
};

}  // namespace og::terrain
