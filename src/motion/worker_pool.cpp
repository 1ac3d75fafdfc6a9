#include "motion/worker_pool.h"

#include <algorithm>

namespace datomsim::motion {

WorkerPool::WorkerPool(int threads)
    : start_(std::max(threads, 1)), finished_(std::max(threads, 1)) {
  for (int w = 1; w < threads; ++w) workers_.emplace_back([this, w] { work(w); });
}

WorkerPool::~WorkerPool() {
  stopping_ = true;
  start_.arrive_and_wait();
  for (std::thread& worker : workers_) worker.join();
}

void WorkerPool::run(const std::function<void(int)>& task) {
  task_ = &task;
  start_.arrive_and_wait();
  task(0);
  finished_.arrive_and_wait();
}

void WorkerPool::work(int worker) {
  for (;;) {
    start_.arrive_and_wait();
    if (stopping_) return;
    (*task_)(worker);
    finished_.arrive_and_wait();
  }
}

int threadsFor(int requested) {
  if (requested > 0) return requested;
  return std::max(1, int(std::thread::hardware_concurrency()));
}

}  // namespace datomsim::motion
