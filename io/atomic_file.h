// Writing output files so that a failed or interrupted write never leaves a partial file
// behind and never overwrites an input of the run.
//
// AtomicFile writes into an unnamed temporary file (O_TMPFILE) in the target's directory and
// links it into place on commit(): killed at any moment, even by SIGKILL, it leaves nothing.
// Where the file system has no O_TMPFILE it writes a named temporary `.NAME.tmp-XXXXXX`
// beside the target instead, registered for removal on SIGINT/SIGTERM (signal_cleanup.h), and
// renames it over the target on commit(). Destroying an AtomicFile that was not committed
// discards the temporary file.
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
  /// The kind of temporary file: unnamed where the file system allows it, or always named (the
  /// fallback, chosen explicitly so that it can be tested on any file system).
  enum class Temporary { unnamed_if_possible, named };

  /// Creates the temporary file in the directory of `target`.
  /// \throws OutputError when `target` is protected, is a directory, or the temporary file
  /// cannot be created (missing directory, permissions).
  AtomicFile(const std::string& target, const std::vector<std::string>& protected_paths,
             Temporary temporary = Temporary::unnamed_if_possible);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  std::ostream& stream() { return out_; }
  /// Flushes and closes the stream. \throws OutputError on any write error.
  void close();
  /// close(), then puts the file in place of the target. \throws OutputError
  void commit();

  const std::string& target() const { return target_; }
  /// True when the temporary file has no name (O_TMPFILE).
  bool unnamed() const { return unnamed_fd_ >= 0; }

 private:
  void discard() noexcept;
  /// A named temporary beside the target, registered for removal on a signal.
  void create_named(const std::string& pattern);
  /// Gives the unnamed file the name `name`. \returns false (errno set) on failure.
  bool link_unnamed(const std::string& name) const;

  std::string target_;
  std::string temp_;       // named temporary (empty while unnamed or after commit)
  int temp_slot_ = -1;     // its slot in the signal cleanup registry
  int unnamed_fd_ = -1;    // the O_TMPFILE descriptor
  std::string directory_;  // where the temporary lives
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
