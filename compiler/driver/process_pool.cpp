#include "compiler/driver/process_pool.h"

#include <fcntl.h>
#include <sched.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

namespace sled::driver {
namespace {

volatile std::sig_atomic_t g_interrupt = 0;

void OnInterrupt(int signal) { g_interrupt = signal; }

// Installs the interrupt handlers for the pool's lifetime, without SA_RESTART so that a blocked
// waitpid returns; restores the previous ones after.
class InterruptGuard {
 public:
  InterruptGuard() {
    g_interrupt = 0;
    struct sigaction action {};
    action.sa_handler = OnInterrupt;
    sigemptyset(&action.sa_mask);
    for (std::size_t i = 0; i < kSignals.size(); ++i) sigaction(kSignals[i], &action, &old_[i]);
  }
  ~InterruptGuard() {
    for (std::size_t i = 0; i < kSignals.size(); ++i) sigaction(kSignals[i], &old_[i], nullptr);
  }
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

 private:
  static constexpr std::array<int, 3> kSignals = {SIGINT, SIGTERM, SIGHUP};
  std::array<struct sigaction, 3> old_{};
};

// In the child: stdin from /dev/null, stdout and stderr to the log, default signal handling.
void PrepareChild(const ProcessJob& job) {
  for (const int signal : {SIGINT, SIGTERM, SIGHUP}) std::signal(signal, SIG_DFL);
  const int null_in = open("/dev/null", O_RDONLY);
  if (null_in >= 0) {
    dup2(null_in, STDIN_FILENO);
    close(null_in);
  }
  if (!job.log_path.empty()) {
    const int log = open(job.log_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (log >= 0) {
      dup2(log, STDOUT_FILENO);
      dup2(log, STDERR_FILENO);
      close(log);
    }
  }
}

[[noreturn]] void RunChild(const ProcessJob& job) {
  PrepareChild(job);
  if (job.body) {
    int code = 1;
    try {
      code = job.body();
    } catch (const std::exception& error) {
      std::fprintf(stderr, "sled: internal error in a worker: %s\n", error.what());
    }
    std::fflush(stdout);
    std::fflush(stderr);
    _exit(code);
  }
  std::vector<char*> argv;
  for (const std::string& arg : job.argv) argv.push_back(const_cast<char*>(arg.c_str()));
  argv.push_back(nullptr);
  execv(argv[0], argv.data());
  std::fprintf(stderr, "sled: cannot run `%s`\n", job.argv.empty() ? "" : job.argv[0].c_str());
  _exit(127);
}

}  // namespace

bool ProcessOutcome::interrupted() const {
  // A program that catches the signal to save its work exits 128 + the signal (sled run does).
  for (const int stop : {SIGINT, SIGTERM, SIGHUP}) {
    if (exit_code == 128 + stop) return true;
  }
  return signal == SIGINT || signal == SIGTERM || signal == SIGHUP || signal == SIGKILL;
}

int AvailableCores() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof(set), &set) == 0) {
    const int count = CPU_COUNT(&set);
    if (count > 0) return count;
  }
  const long online = sysconf(_SC_NPROCESSORS_ONLN);
  return online > 0 ? static_cast<int>(online) : 1;
}

std::string SelfExecutable() {
  std::error_code error;
  const auto path = std::filesystem::read_symlink("/proc/self/exe", error);
  return error ? std::string("sled") : path.string();
}

bool RunProcesses(const std::vector<ProcessJob>& jobs, int workers,
                  const std::function<void(std::size_t)>& on_start,
                  const std::function<void(std::size_t, const ProcessOutcome&)>& on_done) {
  using Clock = std::chrono::steady_clock;
  InterruptGuard guard;
  struct Running {
    std::size_t job;
    Clock::time_point start;
  };
  std::map<pid_t, Running> running;
  std::vector<std::pair<std::size_t, ProcessOutcome>> ended;  // not yet given to on_done
  std::size_t next = 0;
  bool signalled_children = false;
  std::fflush(stdout);
  std::fflush(stderr);
  // Takes an ended child's status (a process not started here is left alone).
  auto reap = [&](pid_t pid, int status) {
    const auto it = running.find(pid);
    if (it == running.end()) return;
    ProcessOutcome outcome;
    outcome.wall_seconds = std::chrono::duration<double>(Clock::now() - it->second.start).count();
    if (WIFEXITED(status)) outcome.exit_code = WEXITSTATUS(status);
    if (WIFSIGNALED(status)) outcome.signal = WTERMSIG(status);
    ended.emplace_back(it->second.job, outcome);
    running.erase(it);
  };
  while (next < jobs.size() || !running.empty() || !ended.empty()) {
    // Free slots are filled first and the ended jobs' bookkeeping done after, while the new
    // children already run: a worker never waits for the parent's writing.
    while (g_interrupt == 0 && next < jobs.size() &&
           static_cast<int>(running.size()) < std::max(1, workers)) {
      if (on_start) on_start(next);
      std::fflush(stdout);
      std::fflush(stderr);
      const pid_t pid = fork();
      if (pid == 0) RunChild(jobs[next]);
      if (pid < 0) {
        // No process to be had: run nothing more, report this job as not started.
        ProcessOutcome outcome;
        outcome.exit_code = 127;
        ended.emplace_back(next, outcome);
        ++next;
        continue;
      }
      running[pid] = {next, Clock::now()};
      ++next;
    }
    for (const auto& [job, outcome] : ended) {
      if (on_done) on_done(job, outcome);
    }
    ended.clear();
    if (g_interrupt != 0 && !signalled_children) {
      for (const auto& [pid, job] : running) kill(pid, g_interrupt);
      signalled_children = true;
      next = jobs.size();
    }
    if (running.empty()) {
      if (next < jobs.size()) continue;
      break;
    }
    int status = 0;
    const pid_t pid = waitpid(-1, &status, 0);
    if (pid < 0) {
      if (errno == EINTR) continue;
      break;  // no children left to wait for
    }
    reap(pid, status);
    // Others that ended meanwhile: their slots are filled together.
    for (pid_t more = 0; (more = waitpid(-1, &status, WNOHANG)) > 0;) reap(more, status);
  }
  return g_interrupt == 0;
}

bool RunInWorkers(std::size_t count, int workers,
                  const std::function<std::string(std::size_t)>& work,
                  std::vector<std::optional<std::string>>* results,
                  const std::function<void(std::size_t)>& on_done) {
  // Each child leaves its result in a file of a private folder, read once the child has ended
  // (a pipe would need reading while the children run).
  std::string folder = (std::filesystem::temp_directory_path() / "sled_workers_XXXXXX").string();
  if (mkdtemp(folder.data()) == nullptr)
    throw std::runtime_error("cannot create a folder for workers");
  auto result_path = [&](std::size_t i) { return folder + "/" + std::to_string(i); };
  std::vector<ProcessJob> jobs(count);
  for (std::size_t i = 0; i < count; ++i) {
    jobs[i].body = [&, i] {
      const std::string bytes = work(i);
      // Read back as soon as the child ends and then removed: no fsync, which would make every
      // worker wait for the disk. A short write ends the child with 1, and its result is lost.
      std::ofstream out(result_path(i), std::ios::binary | std::ios::trunc);
      out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
      out.close();
      return out ? 0 : 1;
    };
  }
  results->assign(count, std::nullopt);
  const bool finished =
      RunProcesses(jobs, workers, {}, [&](std::size_t i, const ProcessOutcome& outcome) {
        if (outcome.exit_code == 0) {
          std::ifstream in(result_path(i), std::ios::binary);
          std::ostringstream bytes;
          bytes << in.rdbuf();
          if (in) (*results)[i] = bytes.str();
        }
        if (on_done) on_done(i);
      });
  std::error_code error;
  std::filesystem::remove_all(folder, error);
  return finished;
}

}  // namespace sled::driver
