#include "drive_processes.h"

#include <cerrno>
#include <chrono>
#include <csignal>
#include <map>
#include <thread>

#include <fcntl.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include "roadscale/util/error.h"

namespace roadscale::cli {
namespace {

using Clock = std::chrono::steady_clock;

struct Running {
  size_t index;
  Clock::time_point start;
};

// Forks and execs one drive; everything the child does between fork and exec is
// async-signal-safe (the batch may have other threads).
pid_t Start(const std::string& program, const DriveProcess& process) {
  const int log = open(process.log_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (log < 0) ThrowFileError(process.log_path, std::string("cannot open: ") + ErrnoReason(errno));
  const int null = open("/dev/null", O_RDONLY | O_CLOEXEC);
  std::vector<std::string> words = {"roadscale"};
  words.insert(words.end(), process.arguments.begin(), process.arguments.end());
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid == 0) {
    setpgid(0, 0);
    prctl(PR_SET_PDEATHSIG, SIGTERM);
    if (getppid() != parent) _exit(127);  // the batch died before prctl
    if (null >= 0) dup2(null, STDIN_FILENO);
    dup2(log, STDOUT_FILENO);
    dup2(log, STDERR_FILENO);
    execv(program.c_str(), argv.data());
    const char message[] = "roadscale: error: batch: cannot start the roadscale binary\n";
    [[maybe_unused]] const ssize_t written = write(STDERR_FILENO, message, sizeof(message) - 1);
    _exit(127);
  }
  const int fork_error = errno;
  close(log);
  if (null >= 0) close(null);
  if (pid < 0)
    throw Error(std::string("batch: cannot start a process: ") + ErrnoReason(fork_error));
  return pid;
}

int ExitStatus(int wait_status) {
  if (WIFEXITED(wait_status)) return WEXITSTATUS(wait_status);
  if (WIFSIGNALED(wait_status)) return 128 + WTERMSIG(wait_status);
  return 1;
}

}  // namespace

void RunDriveProcesses(const std::string& program, const std::vector<DriveProcess>& processes,
                       int jobs, const std::atomic<bool>& stop,
                       const std::function<void(size_t)>& started,
                       const std::function<void(size_t, const DriveExit&)>& ended) {
  std::map<pid_t, Running> running;
  size_t next = 0;
  bool stopping = false;
  while (running.size() > 0 || (next < processes.size() && !stopping)) {
    if (stop && !stopping) {
      stopping = true;
      for (const auto& entry : running) kill(entry.first, SIGTERM);
    }
    if (!stopping && next < processes.size() && static_cast<int>(running.size()) < jobs) {
      running[Start(program, processes[next])] = {next, Clock::now()};
      started(next);
      ++next;
      continue;
    }
    // Polled rather than blocking in waitpid: a signal's handler restarts a blocked waitpid,
    // and the stop flag must be seen while drives run.
    int wait_status = 0;
    const pid_t pid = waitpid(-1, &wait_status, WNOHANG);
    if (pid > 0 && running.count(pid) > 0) {
      const Running done = running[pid];
      running.erase(pid);
      DriveExit exit;
      exit.status = ExitStatus(wait_status);
      exit.wall_s = std::chrono::duration<double>(Clock::now() - done.start).count();
      ended(done.index, exit);
      continue;
    }
    if (pid < 0 && errno == ECHILD) break;  // nothing left to wait for
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
}

}  // namespace roadscale::cli
