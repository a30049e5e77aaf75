// Writing output files so that a failed write never leaves a partial file behind and never
// overwrites an input of the run.
//
// AtomicFile writes into a temporary file created in the target's directory (so the final
// rename stays on one file system and is atomic) and renames it over the target on commit().
// Destroying an AtomicFile that was not committed removes the temporary file.
#pragma once

#include <fstream>
#include <functional>
#include <string>
#include <vector>

namespace voroseal {

/// True when `path` designates the same file as one of `protected_paths` (same inode when
/// both exist, else the same weakly canonical path).
bool is_protected_path(const std::string& path, const std::vector<std::string>& protected_paths);

class AtomicFile {
 public:
  /// Creates the temporary file beside `target`.
  /// \throws OutputError when `target` is protected, is a directory, or the temporary file
  /// cannot be created (missing directory, permissions).
  AtomicFile(const std::string& target, const std::vector<std::string>& protected_paths);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  std::ostream& stream() { return out_; }
  /// Flushes and closes the temporary file. \throws OutputError on any write error.
  void close();
  /// close(), then renames the temporary file over the target. \throws OutputError
  void commit();

  const std::string& target() const { return target_; }

 private:
  void discard() noexcept;

  std::string target_;
  std::string temp_;
  std::ofstream out_;
  std::vector<char> buffer_;
  bool closed_ = false;
  bool committed_ = false;
};

/// Writes one file atomically with `write`. Exceptions thrown by `write` propagate after the
/// temporary file is removed. \throws OutputError
void write_atomically(const std::string& target, const std::vector<std::string>& protected_paths,
                      const std::function<void(std::ostream&)>& write);

}  // namespace voroseal
