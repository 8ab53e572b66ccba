#pragma once

#include <exception>
#include <functional>
#include <memory>
#include <optional>
#include <thread>
#include <utility>
#include <vector>

#include "roadscale/pipeline/bounded_queue.h"

namespace roadscale {

// One stage of a threaded run on its own thread. `work` runs once. An exception it ends with
// is kept for Join, and `on_error` runs (on the stage's thread) to cancel the queues around
// the stage, so that the stages before it stop instead of waiting for room. `on_exit` runs
// last in every case, to close the stage's output queue so that the stage after it ends.
class StageThread {
 public:
  StageThread(std::function<void()> work, std::function<void()> on_error,
              std::function<void()> on_exit);
  StageThread(const StageThread&) = delete;
  StageThread& operator=(const StageThread&) = delete;
  ~StageThread();

  // Waits for the stage to end; returns the exception it ended with (null: none).
  std::exception_ptr Join();

 private:
  std::exception_ptr error_;
  std::thread thread_;
};

// The stage between two queues: each item of `in` becomes step(item) in `out`, until `in`
// ends or `out` is cancelled. An error cancels `in`; every way out closes `out`.
template <typename In, typename Out, typename Step>
std::unique_ptr<StageThread> StartQueueStage(BoundedQueue<In>& in, BoundedQueue<Out>& out,
                                             Step step) {
  return std::make_unique<StageThread>(
      [&in, &out, step]() mutable {
        while (std::optional<In> item = in.Pop()) {
          if (!out.Push(step(*item))) break;
        }
      },
      [&in] { in.Cancel(); }, [&out] { out.Close(); });
}

// The run's last stage, on the calling thread: returns the exception `work` ended with (null:
// none) after running `on_error` for it.
std::exception_ptr RunFinalStage(const std::function<void()>& work,
                                 const std::function<void()>& on_error);

// Rethrows the first set error of `errors`, given the latest stage's first: that stage
// stopped the run at the earliest frame.
void RethrowFirstError(const std::vector<std::exception_ptr>& errors);

}  // namespace roadscale
