// Writers never overwrite inputs of the run, never leave partial or temporary files.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <csignal>

#include <filesystem>

#include "framework/core/error.h"
#include "framework/core/signal_cleanup.h"
#include "io/atomic_file.h"
#include "io/model_io.h"
#include "tests/io/io_test_util.h"
#include "tests/support/test_models.h"

namespace voroseal {
namespace {

namespace fs = std::filesystem;

TEST(Writers, RefuseProtectedPathsInAnySpelling) {
  test::ScratchDir dir;
  const StructuralModel m = build_model(test::lattice_box(2, true));
  const std::string input = dir.file("input.obj");
  test::write_text(input, "original\n");
  fs::create_directories(dir.path() / "sub");
  fs::create_hard_link(input, dir.file("hardlink.obj"));
  fs::create_symlink(input, dir.file("symlink.obj"));
  WriteOptions options;
  options.protected_paths = {input};
  const std::vector<std::string> spellings = {input, dir.file("sub/../input.obj"), dir.file("./input.obj"),
                                              dir.file("hardlink.obj"), dir.file("symlink.obj")};
  for (const std::string& target : spellings) {
    SCOPED_TRACE(target);
    EXPECT_THROW(write_model(m, target, options), OutputError);
  }
  EXPECT_EQ(test::read_text(input), "original\n");
  const std::string mesh_input = dir.file("input.mesh");
  test::write_text(mesh_input, "mesh\n");
  options.protected_paths.push_back(mesh_input);
  EXPECT_THROW(write_volume_mesh(test::cube_tet_mesh(), dir.file("sub/../input.mesh"), options), OutputError);
  EXPECT_THROW(write_model(m, dir.file("./input.mesh"), options), OutputError);
  EXPECT_EQ(test::read_text(mesh_input), "mesh\n");
  fs::remove(mesh_input);
  // A protected path given relative to the working directory is the same file.
  const fs::path cwd = fs::current_path();
  fs::current_path(dir.path());
  options.protected_paths = {"input.obj"};
  EXPECT_THROW(write_model(m, input, options), OutputError);
  fs::current_path(cwd);
  EXPECT_EQ(test::read_text(input), "original\n");
  EXPECT_EQ(dir.listing(), (std::vector<std::string>{"hardlink.obj", "input.obj", "sub", "symlink.obj"}));
}

TEST(Writers, ProtectedTetgenCompanionIsRefusedAndNothingIsWritten) {
  test::ScratchDir dir;
  test::write_text(dir.file("mesh.face"), "input\n");
  WriteOptions options;
  options.protected_paths = {dir.file("mesh.face")};
  EXPECT_THROW(write_volume_mesh(test::cube_tet_mesh(), dir.file("mesh.node"), options), OutputError);
  EXPECT_EQ(dir.listing(), std::vector<std::string>{"mesh.face"});
  EXPECT_EQ(test::read_text(dir.file("mesh.face")), "input\n");
}

TEST(Writers, MissingDirectoryFailsWithoutLeavingFiles) {
  test::ScratchDir dir;
  const StructuralModel m = build_model(test::lattice_box(2, false));
  for (const std::string& ext : writable_model_extensions())
    EXPECT_THROW(write_model(m, dir.file("missing/model" + ext)), OutputError) << ext;
  for (const std::string& ext : writable_volume_extensions())
    EXPECT_THROW(write_volume_mesh(test::cube_tet_mesh(), dir.file("missing/mesh" + ext)), OutputError) << ext;
  EXPECT_TRUE(dir.listing().empty());
  // A directory as target.
  fs::create_directories(dir.path() / "model.obj");
  EXPECT_THROW(write_model(m, dir.file("model.obj")), OutputError);
  EXPECT_EQ(dir.listing(), std::vector<std::string>{"model.obj"});
}

TEST(Writers, SuccessLeavesOnlyTheTargets) {
  test::ScratchDir dir;
  const StructuralModel m = build_model(test::lattice_box(2, true));
  std::vector<std::string> expected;
  for (const std::string& ext : writable_model_extensions()) {
    write_model(m, dir.file("model" + ext));
    expected.push_back("model" + ext);
  }
  write_volume_mesh(test::cube_tet_mesh(), dir.file("tets.node"));
  for (const char* name : {"tets.ele", "tets.face", "tets.node"}) expected.push_back(name);
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(dir.listing(), expected);
  // Overwriting an unprotected file replaces it completely.
  test::write_text(dir.file("model.obj"), std::string(1 << 20, 'x'));
  write_model(m, dir.file("model.obj"));
  EXPECT_EQ(read_model(dir.file("model.obj")).parts.size(), m.parts.size());
}

TEST(Writers, FailureWhileWritingKeepsTheOldTargetAndRemovesTheTemporary) {
  test::ScratchDir dir;
  const std::string target = dir.file("out.txt");
  test::write_text(target, "old content\n");
  EXPECT_THROW(write_atomically(target, {},
                                [](std::ostream& out) {
                                  out << "partial";
                                  throw OutputError("simulated failure");
                                }),
               OutputError);
  EXPECT_EQ(test::read_text(target), "old content\n");
  EXPECT_EQ(dir.listing(), std::vector<std::string>{"out.txt"});
  // An AtomicFile dropped without commit leaves nothing either.
  {
    AtomicFile file(dir.file("never.txt"), {});
    file.stream() << "data";
  }
  EXPECT_EQ(dir.listing(), std::vector<std::string>{"out.txt"});
}

// The fallback where the file system has no O_TMPFILE: a named `.NAME.tmp-XXXXXX` that is
// renamed on commit, removed when dropped, and removed by the signal handler.
TEST(Writers, NamedTemporaryIsRenamedOnCommitAndRemovedOtherwise) {
  using Temporary = AtomicFile::Temporary;
  test::ScratchDir dir;
  {
    AtomicFile file(dir.file("out.txt"), {}, Temporary::named);
    EXPECT_FALSE(file.unnamed());
    file.stream() << "new\n";
    const std::vector<std::string> during = dir.listing();
    ASSERT_EQ(during.size(), 1u);
    EXPECT_EQ(during[0].rfind(".out.txt.tmp-", 0), 0u) << during[0];
    file.commit();
  }
  EXPECT_EQ(dir.listing(), std::vector<std::string>{"out.txt"});
  EXPECT_EQ(test::read_text(dir.file("out.txt")), "new\n");
  {
    AtomicFile dropped(dir.file("dropped.txt"), {}, Temporary::named);
    dropped.stream() << "data";
  }
  EXPECT_EQ(dir.listing(), std::vector<std::string>{"out.txt"});

  // SIGTERM while the temporary is open: the handler removes it and exits with 143.
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    install_signal_cleanup();
    AtomicFile file(dir.file("killed.txt"), {}, Temporary::named);
    file.stream() << "partial" << std::flush;
    ::raise(SIGTERM);
    ::_exit(0);  // not reached
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 143);
  EXPECT_EQ(dir.listing(), std::vector<std::string>{"out.txt"});
}

TEST(Writers, ReadOnlyDirectoryIsAnOutputError) {
  if (::geteuid() == 0) GTEST_SKIP() << "root ignores directory permissions";
  test::ScratchDir dir;
  fs::create_directories(dir.path() / "ro");
  fs::permissions(dir.path() / "ro", fs::perms::owner_read | fs::perms::owner_exec);
  const StructuralModel m = build_model(test::lattice_box(2, false));
  EXPECT_THROW(write_model(m, dir.file("ro/model.ts")), OutputError);
  fs::permissions(dir.path() / "ro", fs::perms::owner_all);
  EXPECT_TRUE(fs::is_empty(dir.path() / "ro"));
}

}  // namespace
}  // namespace voroseal
