#include "equiv/event_queue.h"

namespace gcx::equiv {

bool EventQueue::push(std::vector<motion::Event>&& batch) {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [&] { return batches_.size() < capacity_ || cancelled(); });
  if (cancelled()) return false;
  batches_.push_back(std::move(batch));
  changed_.notify_all();
  return true;
}

bool EventQueue::pop(std::vector<motion::Event>& batch) {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [&] { return !batches_.empty() || closed_; });
  if (batches_.empty()) return false;
  batch = std::move(batches_.front());
  batches_.pop_front();
  changed_.notify_all();
  return true;
}

void EventQueue::close() {
  std::lock_guard lock(mutex_);
  closed_ = true;
  changed_.notify_all();
}

void EventQueue::cancel() {
  std::lock_guard lock(mutex_);
  cancelled_ = true;
  batches_.clear();
  changed_.notify_all();
}

void QueueSink::event(const motion::Event& e) {
  if (q_.cancelled()) throw Cancelled{};
  if (tap_) tap_->event(e);
  batch_.push_back(e);
  if (batch_.size() >= size_) flush();
}

void QueueSink::finish() {
  flush();
  if (tap_) tap_->finish();
}

void QueueSink::flush() {
  if (batch_.empty()) return;
  if (!q_.push(std::move(batch_))) throw Cancelled{};
  batch_ = {};
  batch_.reserve(size_);
}

bool QueueSource::next(motion::Event& e) {
  while (i_ >= batch_.size()) {
    if (ended_ || !q_.pop(batch_)) {
      ended_ = true;
      return false;
    }
    i_ = 0;
  }
  e = std::move(batch_[i_++]);
  return true;
}

} // namespace gcx::equiv
