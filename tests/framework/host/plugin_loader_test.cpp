#include "framework/host/plugin_loader.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "framework/core/error.h"
#include "framework/model/model_builder.h"
#include "tests/support/test_models.h"

namespace voroseal {
namespace {

namespace fs = std::filesystem;

TEST(PluginLoader, LoadsTheExamplePluginAndRunsItsModule) {
  ModuleRegistry registry;
  const std::vector<std::string> added = load_plugin(registry, VOROSEAL_EXAMPLE_PLUGIN);
  ASSERT_EQ(added, std::vector<std::string>{"example-offset"});
  const Module& module = registry.get("example-offset");
  EXPECT_EQ(module.parameters().size(), 3u);

  Logger log(LogLevel::Quiet);
  Progress progress(false);
  Context context(log, progress);
  context.model = std::make_shared<StructuralModel>(build_model(test::lattice_box(2, false)));
  const Vec3 origin = context.model->frame.origin;
  module.run(context, Parameters(module.parameters(), {{"dz", 100.0}, {"dx", "-2.5"}}));
  EXPECT_EQ(context.model->frame.origin, origin + Vec3(-2.5, 0, 100));
  EXPECT_EQ(context.report.at("example-offset").at("triangles"), context.model->num_triangles());
  // Errors thrown inside the plugin are caught as voroseal's own types.
  Context empty(log, progress);
  EXPECT_THROW(module.run(empty, Parameters(module.parameters(), {})), ModelError);
}

TEST(PluginLoader, ALibraryWithoutTheEntryPointIsAClearError) {
  ModuleRegistry registry;
  try {
    load_plugin(registry, VOROSEAL_NOT_A_PLUGIN);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), VOROSEAL_NOT_A_PLUGIN);
    EXPECT_NE(std::string(e.what()).find("voroseal_register_plugin"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(registry.modules().empty());
}

TEST(PluginLoader, AMissingOrBrokenLibraryIsAnInputError) {
  ModuleRegistry registry;
  EXPECT_THROW(load_plugin(registry, "/nonexistent/plugin.so"), InputError);
  // A file that is not a shared library at all.
  const fs::path junk = fs::temp_directory_path() / ("voroseal_junk_" + std::to_string(::getpid()) + ".so");
  { std::ofstream(junk) << "not an ELF file"; }
  EXPECT_THROW(load_plugin(registry, junk.string()), InputError);
  fs::remove(junk);
}

TEST(PluginLoader, RegisteringTheSameModuleTwiceIsAParameterError) {
  ModuleRegistry registry;
  load_plugin(registry, VOROSEAL_EXAMPLE_PLUGIN);
  EXPECT_THROW(load_plugin(registry, VOROSEAL_EXAMPLE_PLUGIN), ParameterError);
  EXPECT_EQ(registry.modules().size(), 1u);
}

TEST(PluginLoader, ASearchPathLoadsTheGoodLibrariesAndReportsTheBadOnes) {
  const std::string good_dir = fs::path(VOROSEAL_EXAMPLE_PLUGIN).parent_path().string();
  const std::string bad_dir = fs::path(VOROSEAL_NOT_A_PLUGIN).parent_path().string();
  const std::string path = bad_dir + "::/nonexistent/dir:" + good_dir;
  const std::vector<std::string> libraries = find_plugin_libraries(path);
  ASSERT_EQ(libraries.size(), 2u);
  EXPECT_EQ(libraries[0], VOROSEAL_NOT_A_PLUGIN);
  EXPECT_EQ(libraries[1], VOROSEAL_EXAMPLE_PLUGIN);

  ModuleRegistry registry;
  const PluginLoadReport report = load_plugins(registry, path);
  EXPECT_EQ(report.loaded, std::vector<std::string>{VOROSEAL_EXAMPLE_PLUGIN});
  EXPECT_EQ(report.modules, std::vector<std::string>{"example-offset"});
  ASSERT_EQ(report.errors.size(), 1u);
  EXPECT_NE(report.errors[0].find("not a voroseal plugin"), std::string::npos);
  EXPECT_NE(registry.find("example-offset"), nullptr);
  // A file given directly in the path is taken as a library.
  EXPECT_EQ(find_plugin_libraries(VOROSEAL_EXAMPLE_PLUGIN), std::vector<std::string>{VOROSEAL_EXAMPLE_PLUGIN});
  EXPECT_TRUE(find_plugin_libraries("").empty());
}

}  // namespace
}  // namespace voroseal
