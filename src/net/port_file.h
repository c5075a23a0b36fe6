#pragma once
// PortFileClaim: the port file of `--accept-workers FILE` (net/invitation.h says what it holds),
// written so that it cannot be turned against anyone, and held by one render at a time.
//
//   - Never through a link. A symbolic link at FILE is refused (whoever can write the folder
//     could otherwise point it at any file, and a render run by root would replace that file
//     with the secret). The contents go to a temporary file beside FILE created with
//     O_CREAT|O_EXCL|O_NOFOLLOW, mode 0600 from the start, synced, then linked in as FILE
//     (link(2) never replaces a file); a rename(2) replaces only a stale port file, and never
//     follows a link either.
//   - One render at a time. The render keeps an exclusive flock(2) on its port file while it
//     runs: a FILE that is locked belongs to a running render and is refused (the running one's
//     secret stays, and its joiners with it). An unlocked one is a port file left by a render
//     that was killed, and is replaced. Any other file at FILE (not a port file) is refused
//     rather than lost.
//   - release() (and the destructor) removes FILE, if it is still this render's, and drops
//     the lock.
// Where the file system has no flock (some network file systems), the one-render check is
// skipped: the file is still written as above.

#include <sys/types.h>

#include <string>

namespace prt {

class PortFileClaim {
 public:
  // Writes `text` to `path` as above. Throws InputError saying why it would not.
  PortFileClaim(const std::string& path, const std::string& text);
  ~PortFileClaim();
  PortFileClaim(PortFileClaim&& other) noexcept;
  PortFileClaim& operator=(PortFileClaim&& other) noexcept;
  PortFileClaim(const PortFileClaim&) = delete;
  PortFileClaim& operator=(const PortFileClaim&) = delete;

  const std::string& path() const { return path_; }
  // Removes the file when it is still the one this claim wrote; idempotent.
  void release();

 private:
  std::string path_;
  int fd_ = -1;  // open on the file, holding its lock
  dev_t device_ = 0;
  ino_t inode_ = 0;
};

}  // namespace prt
