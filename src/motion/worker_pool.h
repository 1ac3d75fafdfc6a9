// Threads that run one task split by worker, again and again: a breadth-first search's frontiers,
// one at a time (motion/model_search.h). The calling thread is worker 0, so a pool of one thread
// starts none.
#pragma once

#include <barrier>
#include <functional>
#include <thread>
#include <vector>

namespace datomsim::motion {

class WorkerPool {
 public:
  explicit WorkerPool(int threads);
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  // Calls task(w) for every worker w in [0, threads) at once, and returns when every call has.
  // The task must not throw.
  void run(const std::function<void(int)>& task);

 private:
  void work(int worker);

  // Every worker waits at `start_` for a task and at `finished_` for the others to end it: the
  // barriers order the task's writes before the caller's reads.
  std::barrier<> start_;
  std::barrier<> finished_;
  const std::function<void(int)>* task_ = nullptr;
  bool stopping_ = false;
  std::vector<std::thread> workers_;
};

// The threads a search uses when asked for `requested`: 0 means every core.
int threadsFor(int requested);

}  // namespace datomsim::motion
