#include "rfReadInChild.h"

#include <vtkAlgorithm.h>

#if defined(__unix__) || defined(__APPLE__)
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>
#define RF_READ_IN_CHILD 1
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
    const int quiet = open("/dev/null", O_WRONLY);
    if (quiet >= 0)
    {
      dup2(quiet, 1);
      dup2(quiet, 2);
    }
    reader->Update();
    _exit(0);
  }
  int status = 0;
  while (waitpid(child, &status, 0) < 0)
  {
    if (errno != EINTR)
    {
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
