#include "roadscale/pipeline/stage_thread.h"

namespace roadscale {

StageThread::StageThread(std::function<void()> work, std::function<void()> on_error,
                         std::function<void()> on_exit)
    : thread_([this, work = std::move(work), on_error = std::move(on_error),
               on_exit = std::move(on_exit)] {
        try {
          work();
        } catch (...) {
          error_ = std::current_exception();
          on_error();
        }
        on_exit();
      }) {}

StageThread::~StageThread() {
  if (thread_.joinable()) thread_.join();
}

std::exception_ptr StageThread::Join() {
  if (thread_.joinable()) thread_.join();
  return error_;
}

std::exception_ptr RunFinalStage(const std::function<void()>& work,
                                 const std::function<void()>& on_error) {
  try {
    work();
  } catch (...) {
    on_error();
    return std::current_exception();
  }
  return nullptr;
}

void RethrowFirstError(const std::vector<std::exception_ptr>& errors) {
  for (const std::exception_ptr& error : errors) {
    if (error) std::rethrow_exception(error);
  }
}

}  // namespace roadscale
