#include "io/formats/output_lock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <thread>

#include "io/formats/input_error.h"

namespace hullopt::io {
namespace {

std::string ReadAll(int fd) {
  std::string text;
  char buf[512];
  if (::lseek(fd, 0, SEEK_SET) < 0) return text;
  ssize_t n = 0;
  while ((n = ::read(fd, buf, sizeof buf)) > 0) text.append(buf, static_cast<std::size_t>(n));
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  return text;
}

std::string Holder(const std::string& command) {
  char host[256] = "unknown";
  ::gethostname(host, sizeof host - 1);
  char when[64] = "";
  const std::time_t now = std::time(nullptr);
  std::tm tm{};
  ::gmtime_r(&now, &tm);
  std::strftime(when, sizeof when, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return "pid " + std::to_string(::getpid()) + " on host " + host + ", hullopt " + command + ", started " +
         when;
}

}  // namespace

OutputFolderLock::OutputFolderLock(const std::string& dir, const std::string& command, std::string* stale)
    : dir_(dir), path_((std::filesystem::path(dir) / FileName()).string()) {
  std::error_code ec;
  created_dir_ = std::filesystem::create_directories(dir, ec);
  if (ec) throw InputError(dir + ": cannot create output folder: " + ec.message());
  // Open, lock, and check that the path still names the locked file: a run that removed its empty folder
  // (see the destructor) may have unlinked it between our open and our flock.
  for (int attempt = 0; attempt < 100; ++attempt) {
    fd_ = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ < 0) throw InputError(path_ + ": cannot open the output folder's lock file: " + std::strerror(errno));
    if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
      const int err = errno;
      // The holder writes its identity right after taking the lock: give it a moment, so that two runs
      // started together still name each other.
      std::string holder = ReadAll(fd_);
      for (int wait = 0; holder.empty() && err == EWOULDBLOCK && wait < 50; ++wait) {
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
        holder = ReadAll(fd_);
      }
      ::close(fd_);
      fd_ = -1;
      if (err != EWOULDBLOCK)
        throw InputError(path_ + ": cannot lock the output folder: " + std::strerror(err));
      throw InputError(dir + ": the output folder is in use by another hullopt process (" +
                       (holder.empty() ? std::string("which is just starting") : holder) +
                       "); one folder takes one run at a time: wait for it to finish or use another --out");
    }
    struct stat by_fd{}, by_path{};
    if (::fstat(fd_, &by_fd) == 0 && ::stat(path_.c_str(), &by_path) == 0 && by_fd.st_ino == by_path.st_ino &&
        by_fd.st_dev == by_path.st_dev)
      break;
    ::close(fd_);
    fd_ = -1;
    std::filesystem::create_directories(dir, ec);
  }
  if (fd_ < 0) throw InputError(path_ + ": cannot lock the output folder (its lock file keeps changing)");
  const std::string previous = ReadAll(fd_);
  if (stale) *stale = previous;  // a holder that released cleanly leaves the file empty
  const std::string me = Holder(command) + "\n";
  if (::ftruncate(fd_, 0) != 0 || ::pwrite(fd_, me.data(), me.size(), 0) != static_cast<ssize_t>(me.size()))
    throw InputError(path_ + ": cannot write the output folder's lock file: " + std::strerror(errno));
}

OutputFolderLock::~OutputFolderLock() {
  if (fd_ < 0) return;
  bool remove_dir = false;
  if (created_dir_) {
    std::error_code ec;
    remove_dir = true;
    for (const auto& e : std::filesystem::directory_iterator(dir_, ec))
      if (e.path().filename() != FileName()) remove_dir = false;
    if (ec) remove_dir = false;
  }
  if (remove_dir) {
    ::unlink(path_.c_str());  // while still locked: a process waiting on the old file re-checks the path
  } else if (::ftruncate(fd_, 0) != 0) {
    // An unreleased description only makes the next run report a stale lock; nothing to do here.
  }
  ::close(fd_);
  if (remove_dir) {
    std::error_code ec;
    std::filesystem::remove(dir_, ec);
  }
}

}  // namespace hullopt::io
