#include "tools/lsp/run_worker.h"

#include <algorithm>

#include "tools/lsp/cell_checked_run.h"

namespace rs::lsp {

RunWorker::RunWorker(Done done) : done_(std::move(done)), thread_([this] { loop(); }) {}

RunWorker::~RunWorker() {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
    queue_.clear();
    if (running_) running_->runControl().abandon();
  }
  wake_.notify_all();
  thread_.join();
}

void RunWorker::submit(RunJob job) {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    const auto same = std::find_if(queue_.begin(), queue_.end(), [&](const RunJob& j) { return j.uri == job.uri; });
    if (same != queue_.end()) *same = std::move(job);
    else queue_.push_back(std::move(job));
  }
  wake_.notify_one();
}

void RunWorker::settle() {
  std::unique_lock<std::mutex> lock(mutex_);
  idle_.wait(lock, [this] { return queue_.empty() && !running_; });
}

void RunWorker::setBudget(std::chrono::milliseconds budget) {
  const std::lock_guard<std::mutex> lock(mutex_);
  budget_ = budget;
}

void RunWorker::loop() {
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    wake_.wait(lock, [this] { return stopping_ || !queue_.empty(); });
    if (stopping_) return;
    RunJob job = std::move(queue_.front());
    queue_.pop_front();
    running_ = job.analysis;
    const std::chrono::milliseconds budget = budget_;
    lock.unlock();
    if (job.plan.active()) {
      std::vector<CheckedRun> made =
          checkCellRun(*job.analysis, job.plan, job.options, job.analysis->runControl(), budget);
      for (std::size_t p = 0; p < job.plan.partners.size(); ++p)
        if (job.plan.partners[p].claimed) job.plan.partners[p].analysis->runMade(std::move(made[p + 1]));
      job.analysis->runMade(std::move(made[0]));
    } else {
      job.analysis->runMade(checkRun(*job.analysis, job.options, job.analysis->runControl(), budget));
    }
    done_(job, *job.analysis->run());
    lock.lock();
    running_.reset();
    if (queue_.empty()) idle_.notify_all();
  }
}

}  // namespace rs::lsp
