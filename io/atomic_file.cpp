#include "io/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <system_error>

#include "framework/core/error.h"
#include "framework/core/signal_cleanup.h"

namespace voroseal {

namespace fs = std::filesystem;

bool is_protected_path(const std::string& path, const std::vector<std::string>& protected_paths) {
  std::error_code ec;
  const fs::path target(path);
  const bool target_exists = fs::exists(target, ec);
  const fs::path canonical_target = fs::weakly_canonical(target, ec);
  for (const std::string& p : protected_paths) {
    if (p.empty()) continue;
    std::error_code ec2;
    if (target_exists && fs::exists(p, ec2) && fs::equivalent(target, p, ec2)) return true;
    std::error_code ec3;
    const fs::path canonical = fs::weakly_canonical(p, ec3);
    if (!ec && !ec3 && canonical == canonical_target) return true;
  }
  return false;
}

namespace {

std::string fd_path(int fd) { return "/proc/self/fd/" + std::to_string(fd); }

}  // namespace

AtomicFile::AtomicFile(const std::string& target, const std::vector<std::string>& protected_paths,
                       Temporary temporary)
    : target_(target) {
  if (target.empty()) throw OutputError("empty output file name");
  if (is_protected_path(target, protected_paths))
    throw OutputError(target + ": refusing to overwrite an input of this run");
  std::error_code ec;
  if (fs::is_directory(target, ec)) throw OutputError(target + ": is a directory");
  const fs::path t(target);
  directory_ = t.has_parent_path() ? t.parent_path().string() : std::string(".");
  buffer_.resize(1 << 20);
  out_.rdbuf()->pubsetbuf(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
  (void)temporary;  // without O_TMPFILE every temporary is named
#ifdef O_TMPFILE
  // An unnamed file is reopened through /proc (the stream needs a path) and linked in place
  // by commit(); where either is unsupported the named temporary below takes over.
  if (temporary == Temporary::unnamed_if_possible)
    unnamed_fd_ = ::open(directory_.c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0644);
  if (unnamed_fd_ >= 0) {
    ::fchmod(unnamed_fd_, 0644);
    out_.open(fd_path(unnamed_fd_), std::ios::binary | std::ios::trunc);
    if (out_) return;
    out_.clear();
    ::close(unnamed_fd_);
    unnamed_fd_ = -1;
  }
#endif
  create_named((fs::path(directory_) / ("." + t.filename().string() + ".tmp-XXXXXX")).string());
}

void AtomicFile::create_named(const std::string& pattern) {
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  {
    // mkstemp gives a fresh name atomically, so concurrent writers never share a temporary;
    // signals wait until the file is registered for removal.
    SignalBlock block;
    const int fd = ::mkstemp(name.data());
    if (fd < 0)
      throw OutputError(target_ + ": cannot create a temporary file in " + directory_ + ": " +
                        std::strerror(errno));
    temp_ = name.data();
    temp_slot_ = register_temp_file(temp_.c_str());
    // mkstemp makes the file private (0600); an output file gets ordinary permissions.
    ::fchmod(fd, 0644);
    ::close(fd);
  }
  out_.open(temp_, std::ios::binary | std::ios::trunc);
  if (!out_) {
    discard();
    throw OutputError(target_ + ": cannot open temporary file " + temp_);
  }
}

AtomicFile::~AtomicFile() {
  if (!committed_) discard();
}

void AtomicFile::discard() noexcept {
  if (out_.is_open()) out_.close();
  if (unnamed_fd_ >= 0) ::close(unnamed_fd_);  // an unnamed file vanishes with its descriptor
  unnamed_fd_ = -1;
  if (!temp_.empty()) {
    SignalBlock block;
    std::remove(temp_.c_str());
    unregister_temp_file(temp_slot_);
  }
  temp_slot_ = -1;
  temp_.clear();
}

void AtomicFile::close() {
  if (closed_) return;
  out_.flush();
  const bool ok = static_cast<bool>(out_);
  out_.close();
  closed_ = true;
  if (!ok || out_.fail()) {
    discard();
    throw OutputError(target_ + ": write failed (disk full or I/O error)");
  }
}

bool AtomicFile::link_unnamed(const std::string& name) const {
  return ::linkat(AT_FDCWD, fd_path(unnamed_fd_).c_str(), AT_FDCWD, name.c_str(),
                  AT_SYMLINK_FOLLOW) == 0;
}

void AtomicFile::commit() {
  if (committed_) return;
  close();
  if (unnamed_fd_ >= 0) {
    // A new file is linked in place directly; an existing one is replaced by a rename from a
    // fresh name, with signals held so that the name never stays behind.
    SignalBlock block;
    std::string from;
    if (!link_unnamed(target_)) {
      if (errno != EEXIST) {
        const std::string why = std::strerror(errno);
        discard();
        throw OutputError(target_ + ": cannot link the written file in place: " + why);
      }
      const fs::path t(target_);
      for (int attempt = 0; attempt < 100 && from.empty(); ++attempt) {
        const std::string name =
            (fs::path(directory_) / ("." + t.filename().string() + ".tmp-" +
                                     std::to_string(::getpid()) + "-" + std::to_string(attempt)))
                .string();
        if (link_unnamed(name))
          from = name;
        else if (errno != EEXIST)
          break;
      }
      if (from.empty() || std::rename(from.c_str(), target_.c_str()) != 0) {
        const std::string why = std::strerror(errno);
        if (!from.empty()) std::remove(from.c_str());
        discard();
        throw OutputError(target_ + ": cannot put the written file in place: " + why);
      }
    }
    ::close(unnamed_fd_);
    unnamed_fd_ = -1;
    committed_ = true;
    return;
  }
  if (temp_.empty()) throw OutputError(target_ + ": nothing to commit");
  SignalBlock block;
  if (std::rename(temp_.c_str(), target_.c_str()) != 0) {
    const std::string why = std::strerror(errno);
    discard();
    throw OutputError(target_ + ": cannot rename temporary file: " + why);
  }
  unregister_temp_file(temp_slot_);
  temp_slot_ = -1;
  committed_ = true;
  temp_.clear();
}

void write_atomically(const std::string& target, const std::vector<std::string>& protected_paths,
                      const std::function<void(std::ostream&)>& write) {
  AtomicFile file(target, protected_paths);
  write(file.stream());
  file.commit();
}

}  // namespace voroseal
