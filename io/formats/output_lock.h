#pragma once
// One writer per output folder: an exclusive advisory lock (flock(2)) on DIR/hullopt.lock, held for the whole
// run of a command that writes the folder. The lock file names its holder (pid, host, command, start time) so
// a second process is refused at once with a message naming the first. The kernel drops the lock when the
// holding process dies, however it dies (exit, exception, SIGKILL), so a lock file left by a killed process is
// recognised as stale (the lock can be taken although the file still names a holder) and taken over.
#include <string>

namespace hullopt::io {

class OutputFolderLock {
 public:
  /// Creates dir (and parents) if needed and takes the lock. Throws InputError if the folder cannot be
  /// created or the lock file opened, or if another process holds the lock (the message names it). `stale`
  /// receives the previous holder's description when a lock left by a process that died was taken over.
  OutputFolderLock(const std::string& dir, const std::string& command, std::string* stale = nullptr);
  /// Releases the lock (empties the lock file first). If this lock created the folder and nothing but the
  /// lock file was written into it (the run failed before writing), the folder is removed again.
  ~OutputFolderLock();
  OutputFolderLock(const OutputFolderLock&) = delete;
  OutputFolderLock& operator=(const OutputFolderLock&) = delete;

  /// Name of the lock file inside the folder.
  static const char* FileName() { return "hullopt.lock"; }

 private:
  std::string dir_, path_;
  int fd_ = -1;
  bool created_dir_ = false;
};

}  // namespace hullopt::io
