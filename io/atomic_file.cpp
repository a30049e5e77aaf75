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

AtomicFile::AtomicFile(const std::string& target, const std::vector<std::string>& protected_paths)
    : target_(target) {
  if (target.empty()) throw OutputError("empty output file name");
  if (is_protected_path(target, protected_paths))
    throw OutputError(target + ": refusing to overwrite an input of this run");
  std::error_code ec;
  if (fs::is_directory(target, ec)) throw OutputError(target + ": is a directory");
  const fs::path t(target);
  const fs::path dir = t.has_parent_path() ? t.parent_path() : fs::path(".");
  // mkstemp gives a fresh name atomically, so concurrent writers never share a temporary.
  std::string pattern = (dir / ("." + t.filename().string() + ".tmp-XXXXXX")).string();
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  const int fd = ::mkstemp(name.data());
  if (fd < 0)
    throw OutputError(target + ": cannot create a temporary file in " + dir.string() + ": " + std::strerror(errno));
  temp_ = name.data();
  // mkstemp makes the file private (0600); an output file gets ordinary permissions.
  ::fchmod(fd, 0644);
  ::close(fd);
  buffer_.resize(1 << 20);
  out_.rdbuf()->pubsetbuf(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
  out_.open(temp_, std::ios::binary | std::ios::trunc);
  if (!out_) {
    discard();
    throw OutputError(target + ": cannot open temporary file " + temp_);
  }
}

AtomicFile::~AtomicFile() {
  if (!committed_) discard();
}

void AtomicFile::discard() noexcept {
  if (out_.is_open()) out_.close();
  if (!temp_.empty()) std::remove(temp_.c_str());
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

void AtomicFile::commit() {
  if (committed_) return;
  close();
  if (temp_.empty()) throw OutputError(target_ + ": nothing to commit");
  if (std::rename(temp_.c_str(), target_.c_str()) != 0) {
    const std::string why = std::strerror(errno);
    discard();
    throw OutputError(target_ + ": cannot rename temporary file: " + why);
  }
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
