#pragma once

#include <atomic>
#include <functional>
#include <string>
#include <vector>

namespace roadscale::cli {

// A drive's `roadscale run` as a process of its own.
struct DriveProcess {
  std::vector<std::string> arguments;  // after the program name
  std::string log_path;                // its stdout and stderr
};

// How a drive's process ended.
struct DriveExit {
  int status = 0;  // its exit status; 128 + N when signal N ended it; 127 when it did not start
  double wall_s = 0.0;
};

// Runs `program` once per entry of `processes`, at most `jobs` at a time, each in its own
// process group with stdin from /dev/null (so that Ctrl-C on the terminal reaches the batch
// alone, which then passes one SIGTERM to each running drive: each stops after its frames in
// flight, as `roadscale run` does). Each process ends when the batch process dies
// (PR_SET_PDEATHSIG). When `stop` becomes true, no more processes start and the running ones
// get that SIGTERM. Calls `started(i)` and `ended(i, exit)` from this thread. Throws Error
// when a log cannot be opened or a process cannot be forked.
void RunDriveProcesses(const std::string& program, const std::vector<DriveProcess>& processes,
                       int jobs, const std::atomic<bool>& stop,
                       const std::function<void(size_t)>& started,
                       const std::function<void(size_t, const DriveExit&)>& ended);

}  // namespace roadscale::cli
