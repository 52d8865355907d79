// Handing one side's motion events from its producer thread to the comparer: a bounded queue
// of event batches (a batch per lock keeps synchronisation cheap; the bound keeps memory flat
// however long the program), a sink that fills it, and a source that drains it.
#pragma once
#include <atomic>
#include <condition_variable>
#include <deque>
#include <mutex>
#include <vector>

#include "equiv/walker.h"

namespace gcx::equiv {

class EventQueue {
public:
  explicit EventQueue(std::size_t capacity = 8) : capacity_(capacity) {}
  /// Blocks while the queue is full; false once the consumer has cancelled.
  bool push(std::vector<motion::Event>&& batch);
  /// Blocks while the queue is empty and open; false at the end.
  bool pop(std::vector<motion::Event>& batch);
  /// The producer is done (no more batches).
  void close();
  /// The consumer needs no more: producers stop at their next event.
  void cancel();
  bool cancelled() const { return cancelled_.load(std::memory_order_relaxed); }

private:
  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<std::vector<motion::Event>> batches_;
  std::size_t capacity_;
  bool closed_ = false;
  std::atomic<bool> cancelled_{false};
};

/// Thrown by QueueSink into the producing interpreter when the comparison needs no more events.
struct Cancelled {};

/// Fills the queue in batches; also hands every event to `tap` (on the producer's thread).
class QueueSink : public motion::Sink {
public:
  explicit QueueSink(EventQueue& q, motion::Sink* tap = nullptr, std::size_t batch = 1024)
      : q_(q), tap_(tap), size_(batch) {}
  void event(const motion::Event& e) override;
  void finish() override;
  void flush();

private:
  EventQueue& q_;
  motion::Sink* tap_;
  std::size_t size_;
  std::vector<motion::Event> batch_;
};

class QueueSource : public EventSource {
public:
  explicit QueueSource(EventQueue& q) : q_(q) {}
  bool next(motion::Event& e) override;
  /// Whether the comparison read to the end of this stream.
  bool ended() const { return ended_; }

private:
  EventQueue& q_;
  std::vector<motion::Event> batch_;
  std::size_t i_ = 0;
  bool ended_ = false;
};

} // namespace gcx::equiv
