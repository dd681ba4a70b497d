#include "rfReadInChild.h"

#include <vtkAlgorithm.h>
#include <vtkSMPTools.h>

#if defined(__unix__) || defined(__APPLE__)
#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <iterator>
#include <string>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>
#define RF_READ_IN_CHILD 1
#endif

#ifdef RF_READ_IN_CHILD
// Set by a program built with a sanitizer (a fuzzer sets a callback that writes the input as
// a finding); absent, and null, elsewhere.
extern "C" void __sanitizer_set_death_callback(void (*callback)(void)) __attribute__((weak));

namespace
{
// The processor time the child has used, in clock ticks (Linux: /proc/PID/stat's utime and
// stime); -1 where it cannot be read.
long long ChildTicks(pid_t child)
{
  std::ifstream stat("/proc/" + std::to_string(child) + "/stat");
  std::string text((std::istreambuf_iterator<char>(stat)), std::istreambuf_iterator<char>());
  // The command name, in parentheses, may hold spaces: the fields are counted after it.
  const size_t close = text.rfind(')');
  if (close == std::string::npos)
  {
    return -1;
  }
  const char* fields = text.c_str() + close + 2;
  long long utime = 0;
  long long stime = 0;
  // state ppid pgrp session tty_nr tpgid flags minflt cminflt majflt cmajflt utime stime
  if (std::sscanf(fields, "%*c %*d %*d %*d %*d %*d %*u %*u %*u %*u %*u %lld %lld", &utime,
        &stime) != 2)
  {
    return -1;
  }
  return utime + stime;
}

void Nap(long nanoseconds)
{
  const timespec wait = { 0, nanoseconds };
  nanosleep(&wait, nullptr);
}
}
#endif

bool rfReadsWithoutCrashing(vtkAlgorithm* reader, std::string& error)
{
#ifdef RF_READ_IN_CHILD
  std::fflush(nullptr);
  const pid_t child = fork();
  if (child < 0)
  {
    return true; // no child to spare: the reader runs as usual
  }
  if (child == 0)
  {
    // Dies of the signal it gets, whatever handlers the process installed (a sanitizer's, a
    // fuzzer's): the parent tells what happened. Its messages are the parent's to give, when
    // the parent reads again.
    for (int s : { SIGSEGV, SIGBUS, SIGABRT, SIGFPE, SIGILL })
    {
      std::signal(s, SIG_DFL);
    }
    // A reader the sanitizer stops in the child (an allocation too large) is the parent's to
    // refuse, not a fuzzer's finding.
    if (__sanitizer_set_death_callback)
    {
      __sanitizer_set_death_callback(nullptr);
    }
    const int quiet = open("/dev/null", O_WRONLY);
    if (quiet >= 0)
    {
      dup2(quiet, 1);
      dup2(quiet, 2);
    }
    // Only the forking thread lives on in the child: VTK's thread pool (TBB's workers) would
    // be waited for and never come (a reader computing its bounds hung so).
    vtkSMPTools::SetBackend("Sequential");
    reader->Update();
    _exit(0);
  }
  // The child runs until it ends; one that stops using the processor for 5 seconds is stuck
  // on something the fork left behind (a lock another thread held), which says nothing of the
  // file: it is stopped, and the reader runs as usual. A slow disk looks the same and costs
  // only the guard.
  int status = 0;
  long long ticks = -1;
  double still = 0.0;
  long nap = 1000000; // 1 ms, growing to 100 ms
  for (;;)
  {
    const pid_t ended = waitpid(child, &status, WNOHANG);
    if (ended == child)
    {
      break;
    }
    if (ended < 0 && errno != EINTR)
    {
      return true;
    }
    Nap(nap);
    still += nap * 1e-9;
    nap = std::min(nap * 2, 100000000L);
    const long long now = ChildTicks(child);
    if (now != ticks)
    {
      ticks = now;
      still = 0.0;
    }
    else if (now >= 0 && still > 5.0)
    {
      kill(child, SIGKILL);
      waitpid(child, &status, 0);
      std::fprintf(stderr,
        "note: %s, run in a child process first to catch a crash, stalled there; reading "
        "without that guard\n",
        reader->GetClassName());
      return true;
    }
  }
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0)
  {
    return true;
  }
  error = std::string(reader->GetClassName()) + " (VTK) " +
    (WIFSIGNALED(status)
        ? std::string("crashed reading it (") + strsignal(WTERMSIG(status)) + ")"
        : "failed reading it (exit status " + std::to_string(WEXITSTATUS(status)) + ")") +
    ": the file is malformed";
  return false;
#else
  (void)reader;
  (void)error;
  return true;
#endif
}
