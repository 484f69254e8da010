// nbscope core: a few kept worker threads that run one batch of tasks at a time (nbs's bands).
// Threads are started on first need and kept, so a detection does not pay for creating them: it
// pays one wake-up per batch (a few microseconds, which is why small sets run on fewer threads,
// DetectOptions::min_band_elements).
#pragma once
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace nbscope {

class WorkerPool {
 public:
  WorkerPool() = default;
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;
  // Stops and joins the workers.
  ~WorkerPool();
  // Runs task(0) .. task(count - 1), task 0 on the calling thread and the others on workers, and
  // returns when all are done; an exception of a task is rethrown here (the lowest task's first).
  void run(int count, const std::function<void(int)>& task);
  // Worker threads started so far (count - 1 of the largest batch run).
  [[nodiscard]] int workers() const { return static_cast<int>(threads_.size()); }

 private:
  void work(int index);  // worker `index` (1-based: task index) waits for batches until stopped

  std::vector<std::thread> threads_;
  std::mutex mutex_;
  std::condition_variable wake_;  // a new batch, or stop
  std::condition_variable done_;  // the last worker task of a batch finished
  const std::function<void(int)>* task_ = nullptr;
  int count_ = 0;                 // tasks in the current batch
  int pending_ = 0;               // worker tasks of the current batch not finished
  std::uint64_t batch_ = 0;       // bumped for every batch: what a waiting worker watches
  bool stop_ = false;
  std::vector<std::exception_ptr> errors_;  // one per task of the current batch
};

}  // namespace nbscope
