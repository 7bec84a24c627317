#pragma once
// A pool of worker threads that build values from keys (a thread-safe pure function), for the
// caches that fill in the background (terrain tiles: terrain/TileBuilder; imagery tiles:
// data/ImageryTiles). Workers touch nothing but their own queue state and the values they
// build; the caller (the render thread) takes finished values and owns its cache. Each key is
// built at most once while it is queued, in flight or finished but not yet taken.
//
// Key: copyable, with `std::uint64_t packed() const` unique per key. Value: movable and
// default-constructible, with a member `key` (the key it was built from).
#include <algorithm>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <exception>
#include <functional>
#include <mutex>
#include <span>
#include <stop_token>
#include <thread>
#include <unordered_map>
#include <utility>
#include <vector>

namespace og::core {

template <class Key, class Value>
class BuildPool {
 public:
  /// Most background requests kept queued: the latest frame's first (most wanted) ones.
  static constexpr std::size_t kMaxQueued = 512;

  using BuildFn = std::function<Value(const Key&)>;

  /// `workers` <= 0: std::thread::hardware_concurrency() (at least 1).
  explicit BuildPool(BuildFn build, int workers = 0) : build_(std::move(build)) {
    const int n = workers > 0 ? workers : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
    workers_.reserve(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i)
      workers_.emplace_back([this](const std::stop_token& stop) { work(stop); });
  }
  /// Stops and joins the workers; a value in flight is finished first, then dropped.
  ~BuildPool() {
    // Stop them all before joining any (jthread's destructor joins): each finishes its value.
    for (auto& w : workers_) w.request_stop();
  }
  BuildPool(const BuildPool&) = delete;
  BuildPool& operator=(const BuildPool&) = delete;

  /// Builds these keys (in parallel) and blocks until every one of them is finished (keys
  /// already queued or in flight are not built twice). Take them with takeFinished().
  void build(std::span<const Key> keys) {
    std::unique_lock lock(mutex_);
    for (const Key& key : keys) {
      auto [it, fresh] = state_.try_emplace(key.packed());
      Entry& e = it->second;
      if (fresh || e.state == State::Queued) {
        if (!fresh) --queuedCount_;  // its queued_ entry is now skipped
        e.state = State::Urgent;
        urgent_.push_back(key);
      } else if (e.state == State::Done || e.blocking) {
        continue;  // finished, or already counted (a key twice in `keys`)
      }
      e.blocking = true;
      ++blockingLeft_;
    }
    lock.unlock();
    workCv_.notify_all();
    lock.lock();
    doneCv_.wait(lock, [this] { return blockingLeft_ == 0; });
  }

  /// Background requests, in priority order: replace the previous ones still queued (stale
  /// requests are dropped); keys in flight or finished are not queued again. At most kMaxQueued.
  void request(std::span<const Key> keys) {
    {
      std::lock_guard lock(mutex_);
      for (const Key& key : queued_)  // drop what the latest frame no longer asks for
        if (auto it = state_.find(key.packed()); it != state_.end() && it->second.state == State::Queued)
          state_.erase(it);
      queued_.clear();
      queuedCount_ = 0;
      for (const Key& key : keys) {
        if (queuedCount_ == kMaxQueued) break;
        if (!state_.try_emplace(key.packed(), Entry{State::Queued, false}).second) continue;
        queued_.push_back(key);
        ++queuedCount_;
      }
    }
    workCv_.notify_all();
  }

  struct Finished {
    std::vector<Value> tiles;
    std::exception_ptr error;  ///< the first exception a worker threw since the last take
  };
  /// Values finished since the last call (never blocks).
  Finished takeFinished() {
    std::lock_guard lock(mutex_);
    Finished f;
    f.tiles = std::exchange(done_, {});
    f.error = std::exchange(error_, nullptr);
    for (const Value& t : f.tiles) state_.erase(t.key.packed());
    return f;
  }

  /// Keys queued, in flight or finished but not taken.
  [[nodiscard]] std::size_t pending() const {
    std::lock_guard lock(mutex_);
    return state_.size();
  }
  /// Whether this key is queued, in flight or finished but not taken.
  [[nodiscard]] bool isPending(const Key& key) const {
    std::lock_guard lock(mutex_);
    return state_.count(key.packed()) != 0;
  }
  /// Blocks until nothing is queued or in flight (tests, benchmarks).
  void waitIdle() {
    std::unique_lock lock(mutex_);
    doneCv_.wait(lock, [this] { return urgent_.empty() && queuedCount_ == 0 && inFlight_ == 0; });
  }
  [[nodiscard]] int workerCount() const { return static_cast<int>(workers_.size()); }

 private:
  enum class State : std::uint8_t { Queued, Urgent, InFlight, Done };
  struct Entry {
    State state = State::Queued;
    bool blocking = false;  // a build() call waits for it
  };

  /// The next key to build (the lock held, work available).
  Key next() {
    if (!urgent_.empty()) {
      Key key = urgent_.front();
      urgent_.pop_front();
      return key;
    }
    // queuedCount_ != 0: a live entry remains; skip those dropped or taken over by build().
    for (;;) {
      Key key = queued_.front();
      queued_.pop_front();
      const auto it = state_.find(key.packed());
      if (it != state_.end() && it->second.state == State::Queued) {
        --queuedCount_;
        return key;
      }
    }
  }

  void work(const std::stop_token& stop) {
    std::unique_lock lock(mutex_);
    for (;;) {
      workCv_.wait(lock, stop, [this] { return !urgent_.empty() || queuedCount_ != 0; });
      if (stop.stop_requested()) return;
      const Key key = next();
      const std::uint64_t id = key.packed();
      state_[id].state = State::InFlight;
      ++inFlight_;
      lock.unlock();

      Value value;
      std::exception_ptr error;
      try {
        value = build_(key);
      } catch (...) {
        error = std::current_exception();  // handed to the render thread by takeFinished()
      }

      lock.lock();
      --inFlight_;
      const auto it = state_.find(id);
      if (it->second.blocking) --blockingLeft_;
      if (error) {
        state_.erase(it);  // not built: may be asked for again
        if (!error_) error_ = error;
      } else {
        it->second.state = State::Done;
        done_.push_back(std::move(value));
      }
      doneCv_.notify_all();
    }
  }

  BuildFn build_;
  mutable std::mutex mutex_;
  std::condition_variable_any workCv_;  // work arrived (or stop requested)
  std::condition_variable doneCv_;      // a value finished
  std::unordered_map<std::uint64_t, Entry> state_;  // every key queued, in flight or finished
  std::deque<Key> urgent_;       // blocking builds, before any request
  std::deque<Key> queued_;       // background requests (entries no longer Queued are skipped)
  std::size_t queuedCount_ = 0;  // entries of queued_ still in State::Queued
  std::size_t inFlight_ = 0;
  std::size_t blockingLeft_ = 0;  // keys build() still waits for
  std::vector<Value> done_;
  std::exception_ptr error_;
  // Last member: destroyed first, so the threads are joined before the state they use dies.
  std::vector<std::jthread> workers_;
};

}  // namespace og::core
