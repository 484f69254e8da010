// nbscope core: worker_pool.hpp.
#include "core/worker_pool.hpp"

namespace nbscope {

WorkerPool::~WorkerPool() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  for (std::thread& t : threads_) t.join();
}

void WorkerPool::run(int count, const std::function<void(int)>& task) {
  if (count <= 1) {
    if (count == 1) task(0);
    return;
  }
  {
    std::lock_guard lock(mutex_);
    while (static_cast<int>(threads_.size()) < count - 1) {
      const int index = static_cast<int>(threads_.size()) + 1;
      threads_.emplace_back([this, index] { work(index); });
    }
    task_ = &task;
    count_ = count;
    pending_ = count - 1;
    errors_.assign(static_cast<std::size_t>(count), nullptr);
    ++batch_;
  }
  wake_.notify_all();
  try {
    task(0);
  } catch (...) {
    errors_[0] = std::current_exception();  // the workers write only their own entries
  }
  std::unique_lock lock(mutex_);
  done_.wait(lock, [this] { return pending_ == 0; });
  task_ = nullptr;
  for (const std::exception_ptr& e : errors_)
    if (e) std::rethrow_exception(e);
}

void WorkerPool::work(int index) {
  std::uint64_t seen = 0;
  std::unique_lock lock(mutex_);
  for (;;) {
    wake_.wait(lock, [&] { return stop_ || batch_ != seen; });
    if (stop_) return;
    seen = batch_;
    if (index >= count_) continue;  // a smaller batch than this worker
    const std::function<void(int)>* task = task_;
    lock.unlock();
    std::exception_ptr error;
    try {
      (*task)(index);
    } catch (...) {
      error = std::current_exception();
    }
    lock.lock();
    errors_[static_cast<std::size_t>(index)] = error;
    if (--pending_ == 0) done_.notify_one();
  }
}

}  // namespace nbscope
