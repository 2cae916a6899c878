#include "study_tools.h"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <sstream>

#ifndef ISOFORM_STUDY_SCRIPTS_DIR
#define ISOFORM_STUDY_SCRIPTS_DIR ""
#endif

namespace isoform::cli {

std::string study_scripts_folder() {
  const char* env = std::getenv("ISOFORM_STUDY_SCRIPTS");
  return env && *env ? env : ISOFORM_STUDY_SCRIPTS_DIR;
}

std::string find_program(const std::vector<std::string>& candidates) {
  for (const std::string& name : candidates) {
    if (name.find('/') != std::string::npos) {
      if (access(name.c_str(), X_OK) == 0) return name;
      continue;
    }
    const char* path = std::getenv("PATH");
    std::istringstream dirs(path ? path : "/usr/bin:/bin");
    std::string dir;
    while (std::getline(dirs, dir, ':')) {
      const std::string full = (dir.empty() ? "." : dir) + "/" + name;
      if (access(full.c_str(), X_OK) == 0) return full;
    }
  }
  return "";
}

int run_program(const std::vector<std::string>& argv, const std::string& log_path) {
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  const pid_t pid = fork();
  if (pid < 0) return -1;
  if (pid == 0) {
    const int fd = log_path.empty() ? open("/dev/null", O_WRONLY)
                                    : open(log_path.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
    if (fd >= 0) {
      dup2(fd, STDOUT_FILENO);
      dup2(fd, STDERR_FILENO);
      close(fd);
    }
    const int null_in = open("/dev/null", O_RDONLY);
    if (null_in >= 0) dup2(null_in, STDIN_FILENO);
    execv(args[0], args.data());
    _exit(127);
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace isoform::cli
