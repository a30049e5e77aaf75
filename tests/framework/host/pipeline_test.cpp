#include "framework/host/pipeline.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "framework/core/error.h"
#include "framework/host/plugin_loader.h"
#include "framework/host/study_report.h"
#include "framework/model/model_builder.h"
#include "io/model_io.h"
#include "tests/support/test_models.h"

namespace voroseal {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// A module for testing the pipeline: prints `say` on stdout, fails when asked, gives a verdict.
class FakeStep : public Module {
 public:
  std::string name() const override { return "fake-step"; }
  std::string description() const override { return "test step"; }
  std::vector<ParameterSpec> parameters() const override {
    ParameterSpec verdict{"verdict", ParameterType::Int, 0, "exit code to set"};
    verdict.min = 0;
    return {{"fail", ParameterType::Bool, false, "throw a MesherError"},
            verdict,
            {"say", ParameterType::String, "", "text printed on stdout"},
            {"value", ParameterType::Double, 0.0, "a number to sweep"}};
  }
  void run(Context& context, const Parameters& p) const override {
    if (!p.get_string("say").empty()) std::cout << p.get_string("say") << std::endl;
    if (p.get_bool("fail")) throw MesherError("asked to fail");
    context.exit_code = static_cast<int>(p.get_int("verdict"));
    context.report["fake-step"] = {{"value", p.get_double("value")}, {"triangles", context.model->num_triangles()}};
  }
};

ModuleRegistry test_registry() {
  ModuleRegistry registry;
  register_builtin_modules(registry);
  registry.add(std::make_unique<FakeStep>());
  return registry;
}

class TempDir {
 public:
  TempDir() {
    path_ = fs::temp_directory_path() /
            ("voroseal_pipeline_" + std::to_string(::getpid()) + "_" +
             ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~TempDir() { fs::remove_all(path_); }
  std::string operator/(const std::string& name) const { return (path_ / name).string(); }
  std::string str() const { return path_.string(); }

 private:
  fs::path path_;
};

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

Study study_from(json document, const std::string& base = "/base") { return parse_study(document, base, "s.json"); }

void expect_parameter_error(const json& document, const std::string& needle) {
  try {
    study_from(document);
    ADD_FAILURE() << "no error for " << document.dump();
  } catch (const ParameterError& e) {
    EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("s.json"), std::string::npos) << e.what();
  }
}

TEST(StudyFile, MistakesAreNamed) {
  const json steps = json::array({{{"module", "check"}}});
  expect_parameter_error(json::array(), "JSON object");
  expect_parameter_error({{"models", "m.ts"}, {"steps", steps}, {"outptu", "x"}}, "outptu");
  expect_parameter_error({{"steps", steps}}, "models");
  expect_parameter_error({{"models", json::array()}, {"steps", steps}}, "models");
  expect_parameter_error({{"models", {1, 2}}, {"steps", steps}}, "models");
  expect_parameter_error({{"models", "m.ts"}}, "steps");
  expect_parameter_error({{"models", "m.ts"}, {"steps", {{{"modul", "check"}}}}}, "steps[0]");
  expect_parameter_error({{"models", "m.ts"}, {"steps", {{{"module", "check"}, {"params", json::object()}}}}},
                         "steps[0].params");
  expect_parameter_error({{"models", "m.ts"}, {"steps", steps}, {"write", 3}}, "write");
  expect_parameter_error({{"models", "m.ts"}, {"steps", steps}, {"write", {{{"mesh", "a.mesh"}}}}}, "write[0].mesh");
  expect_parameter_error({{"models", "m.ts"}, {"steps", steps}, {"picture", {{"width", 3}}}}, "picture");
  expect_parameter_error({{"models", "m.ts"}, {"steps", steps}, {"name", "a/b"}}, "name");
}

TEST(StudyFile, PathsResolveAgainstTheStudyFolder) {
  const Study study = study_from({{"name", "s1"},
                                  {"models", {"m.ts", "/abs/x.ts"}},
                                  {"steps", {"check", {{"module", "tetmesh"}, {"parameters", {{"quality", 2}}}}}},
                                  {"write", {"model.ml", {{"volume", "v.mesh"}}}},
                                  {"picture", {{"width", 320}, {"perspective", true}}}});
  EXPECT_EQ(study.name, "s1");
  EXPECT_EQ(study.models, (std::vector<std::string>{"/base/m.ts", "/abs/x.ts"}));
  EXPECT_EQ(study.output, (fs::current_path() / "out/s1").string()) << "outputs go where voroseal runs";
  ASSERT_EQ(study.steps.size(), 2u);
  EXPECT_EQ(study.steps[0].module, "check");
  EXPECT_EQ(study.steps[1].parameters.at("quality"), 2);
  ASSERT_EQ(study.write.size(), 2u);
  EXPECT_EQ(study.write[0].what, StudyOutput::What::Auto);
  EXPECT_EQ(study.write[1].what, StudyOutput::What::Volume);
  EXPECT_EQ(study.picture.width, 320);
  EXPECT_EQ(study.picture.height, RenderOptions().height);
  EXPECT_TRUE(study.picture.perspective);
  // The object form of "write", an absolute output, pictures off.
  const Study other = study_from({{"models", "m.ts"},
                                  {"steps", json::array()},
                                  {"output", "/tmp/o"},
                                  {"write", {{"model", {"a.obj", "b.ml"}}, {"volume", "v.vtu"}}},
                                  {"picture", false}});
  EXPECT_EQ(other.name, "s");  // from the file name
  EXPECT_EQ(other.output, "/tmp/o");
  EXPECT_EQ(other.write.size(), 3u);
  EXPECT_FALSE(other.pictures);
}

TEST(StudyFile, ReadStudyReportsUnreadableAndMalformedFiles) {
  TempDir dir;
  EXPECT_THROW(read_study(dir / "missing.json"), InputError);
  std::ofstream(dir / "bad.json") << "{\"models\": [";
  EXPECT_THROW(read_study(dir / "bad.json"), InputError);
  std::ofstream(dir / "ok.json") << "// a comment\n{\"models\": \"m.ts\", \"steps\": [\"check\"]}";
  const Study study = read_study(dir / "ok.json");
  EXPECT_EQ(study.name, "ok");
  EXPECT_EQ(study.models[0], dir / "m.ts");
}

TEST(Sweep, IsTheCrossProductWithTheLastListFastest) {
  const Study study = study_from({{"models", {"a/m1.ts", "b/m2.obj"}},
                                  {"read", {{"feature-angle", {0, 30}}}},
                                  {"steps", {{{"module", "fake-step"}, {"parameters", {{"value", {1, 2.5, 3}}, {"say", "x"}}}}}}});
  const std::vector<StudyRun> runs = expand_study(study);
  ASSERT_EQ(runs.size(), 12u);
  EXPECT_EQ(runs[0].model_label, "m1");
  EXPECT_EQ(runs[0].key, "feature-angle=0_value=1");
  EXPECT_EQ(runs[1].key, "feature-angle=0_value=2.5");
  EXPECT_EQ(runs[3].key, "feature-angle=30_value=1");
  EXPECT_EQ(runs[6].model_label, "m2");
  EXPECT_EQ(runs[11].key, "feature-angle=30_value=3");
  EXPECT_EQ(runs[11].directory, (fs::current_path() / "out/s/m2/feature-angle=30_value=3").string());
  EXPECT_EQ(runs[4].read.at("feature-angle"), 30);
  EXPECT_EQ(runs[4].step_parameters[0].at("value"), 2.5);
  EXPECT_EQ(runs[4].step_parameters[0].at("say"), "x");
  EXPECT_EQ(runs[4].swept, (json{{"feature-angle", 30}, {"value", 2.5}}));
  for (size_t i = 0; i < runs.size(); ++i) EXPECT_EQ(runs[i].index, static_cast<int>(i));
}

TEST(Sweep, NamesAreQualifiedWhenAmbiguousAndFoldersUnique) {
  const Study study = study_from(
      {{"models", {"a/m.ts", "b/m.ts"}},
       {"steps",
        {{{"module", "fake-step"}, {"parameters", {{"value", {1, 2}}}}},
         {{"module", "fake-step"}, {"parameters", {{"value", {3}}, {"say", {"a b", "a/b"}}}}}}}});
  const std::vector<StudyRun> runs = expand_study(study);
  ASSERT_EQ(runs.size(), 8u);
  EXPECT_EQ(runs[0].model_label, "m");
  EXPECT_EQ(runs[4].model_label, "m-2");
  EXPECT_EQ(runs[0].key, "step1.value=1_say=a-b_step2.value=3");  // by name within a step
  EXPECT_EQ(runs[1].key, "step1.value=1_say=a-b_step2.value=3-2");  // "a b" and "a/b" look alike
  EXPECT_TRUE(runs[0].swept.contains("step2.value"));
  // Nothing swept: one run per model, in "default".
  const Study plain = study_from({{"models", "m.ts"}, {"steps", {"check"}}});
  EXPECT_EQ(expand_study(plain).at(0).key, "default");
  // An empty list sweeps nothing.
  EXPECT_THROW(expand_study(study_from({{"models", "m.ts"}, {"read", {{"feature-angle", json::array()}}},
                                        {"steps", json::array()}})),
               ParameterError);
}

TEST(Sweep, ValidationCatchesUnknownModulesAndBadValuesBeforeRunning) {
  const ModuleRegistry registry = test_registry();
  TempDir dir;
  Study study = study_from({{"models", test::bundled_model("folded_layers.ts")},
                            {"output", dir / "out"},
                            {"steps", {{{"module", "fake-stpe"}}}}});
  try {
    validate_study(registry, study, expand_study(study));
    FAIL();
  } catch (const ParameterError& e) {
    EXPECT_NE(std::string(e.what()).find("fake-stpe"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("fake-step"), std::string::npos) << "lists the known modules";
  }
  study.steps = {{"fake-step", {{"verdict", {0, -1}}}}};
  EXPECT_THROW(validate_study(registry, study, expand_study(study)), ParameterError);
  study.steps = {{"fake-step", {{"colour", 1}}}};
  EXPECT_THROW(validate_study(registry, study, expand_study(study)), ParameterError);
  study.steps = {{"fake-step", json::object()}};
  study.read = {{"corner-rule", {"incidence", "nearest"}}};
  Logger log(LogLevel::Quiet);
  Progress progress(false);
  EXPECT_THROW(run_study(registry, study, {}, log, progress), ParameterError);
  EXPECT_FALSE(fs::exists(dir / "out")) << "nothing runs when the study is invalid";
}

TEST(RunStudy, FailedRunsAreRecordedAndTheStudyGoesOn) {
  const ModuleRegistry registry = test_registry();
  TempDir dir;
  const std::string model = test::bundled_model("folded_layers.ts");
  const Study study = study_from(
      {{"name", "t"},
       {"models", {model, dir / "missing.ts"}},
       {"output", dir / "out"},
       {"steps",
        {{{"module", "fake-step"}, {"parameters", {{"fail", {false, true}}, {"say", "hello"}}}},
         {{"module", "tetmesh"}, {"parameters", {{"quality", 0}, {"output", "volume.vtu"}}}}}},
       {"write", {"model.obj", "volume.mesh"}}},
      dir.str());
  Logger log(LogLevel::Quiet);
  Progress progress(false);
  const StudyOutcome outcome = run_study(registry, study, {}, log, progress);
  ASSERT_EQ(outcome.runs.size(), 4u);
  EXPECT_EQ(outcome.failed, 3);
  EXPECT_EQ(outcome.invalid, 0);
  EXPECT_EQ(outcome.exit_code(), 1);

  const RunOutcome& ok = outcome.runs[0];
  const std::string folder = dir / "out/folded_layers/fail=false";
  EXPECT_EQ(ok.run.directory, folder);
  EXPECT_EQ(ok.status, "ok");
  EXPECT_EQ(ok.exit_code, 0);
  EXPECT_EQ(ok.steps[0].status, "ok");
  EXPECT_EQ(ok.steps[1].status, "ok");
  EXPECT_EQ(ok.outputs, (std::vector<std::string>{"folded_layers/fail=false/model.obj",
                                                  "folded_layers/fail=false/volume.mesh"}));
  EXPECT_TRUE(fs::exists(folder + "/volume.vtu")) << "relative path parameters land in the run's folder";
  EXPECT_EQ(read_text(folder + "/step1-fake-step.txt"), "hello\n") << "a step's stdout goes to its file";
  EXPECT_EQ(ok.steps[0].text, "folded_layers/fail=false/step1-fake-step.txt");
  EXPECT_FALSE(fs::exists(folder + "/step2-tetmesh.txt")) << "no file for a step that printed nothing";
  EXPECT_EQ(ok.picture, "folded_layers/fail=false/picture.png");
  EXPECT_EQ(read_text(folder + "/picture.png").substr(1, 3), "PNG");
  EXPECT_EQ(ok.legend.size(), 16u);
  // The measures of the final model (no stats step: measured by the pipeline).
  EXPECT_EQ(ok.measures.at("measured_by"), "pipeline");
  EXPECT_EQ(ok.measures.at("triangles"), 6786);
  EXPECT_EQ(ok.measures.at("vertices"), 3293);
  EXPECT_EQ(ok.measures.at("surfaces"), 16);
  EXPECT_EQ(ok.measures.at("contacts"), 28);
  EXPECT_EQ(ok.measures.at("corners"), 16);
  EXPECT_EQ(ok.measures.at("regions"), 3);
  EXPECT_NEAR(ok.measures.at("min_angle_deg").get<double>(), 36.14, 0.01);
  EXPECT_EQ(ok.measures.at("pct_triangles_angle_below_30"), 0.0);
  EXPECT_TRUE(ok.measures.at("hausdorff_pct").is_null());
  EXPECT_EQ(ok.measures.at("tets"), ok.report.at("tetmesh").at("tets"));
  EXPECT_TRUE(ok.measures.at("thinnest_wedge_deg").is_null()) << "no wedge under 30 degrees in folded_layers";
  EXPECT_TRUE(ok.measures.at("thinnest_border_gap_deg").is_null())
      << "no free border in folded_layers";
  long histogram_total = 0;
  for (const json& c : ok.histograms.at("quality").at("counts")) histogram_total += c.get<long>();
  EXPECT_EQ(histogram_total, 6786);
  // What was written reads back.
  EXPECT_EQ(read_model(folder + "/model.obj").num_triangles(), 6786);
  const json run_file = json::parse(read_text(folder + "/run.json"));
  EXPECT_EQ(run_file.at("status"), "ok");
  EXPECT_EQ(run_file.at("parameters").at("steps")[1].at("parameters").at("output"), folder + "/volume.vtu");
  EXPECT_EQ(run_file.at("parameters").at("steps")[1].at("parameters").at("min-dihedral"), 10.0)
      << "defaults are recorded";
  EXPECT_TRUE(run_file.at("report").contains("tetmesh"));

  const RunOutcome& failed = outcome.runs[1];
  EXPECT_EQ(failed.status, "failed");
  EXPECT_EQ(failed.exit_code, 1);
  EXPECT_EQ(failed.error, "fake-step: meshing failed: asked to fail");
  EXPECT_EQ(failed.steps[0].status, "failed");
  EXPECT_EQ(failed.steps[1].status, "skipped");
  EXPECT_TRUE(failed.outputs.empty());
  EXPECT_EQ(failed.picture, "folded_layers/fail=true/picture.png") << "a failed run's model is pictured";
  const std::string failed_folder = dir / "out/folded_layers/fail=true";
  EXPECT_FALSE(fs::exists(failed_folder + "/model.obj"));
  EXPECT_EQ(json::parse(read_text(failed_folder + "/run.json")).at("status"), "failed");

  for (int r : {2, 3}) {
    EXPECT_EQ(outcome.runs[r].status, "failed");
    EXPECT_EQ(outcome.runs[r].exit_code, 2);
    EXPECT_EQ(outcome.runs[r].error.rfind("read: ", 0), 0u) << outcome.runs[r].error;
    EXPECT_TRUE(outcome.runs[r].picture.empty());
    EXPECT_TRUE(outcome.runs[r].measures.empty());
  }

  // The summary table and the report.
  const std::string csv = read_text(dir / "out/summary.csv");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 5);
  EXPECT_EQ(csv.rfind("run,model,key,fail,status,vertices,triangles,surfaces,contacts,corners,"
                      "regions,min_angle_deg,pct_triangles_angle_below_30,avg_quality,min_quality,"
                      "area,bbox_diagonal,hausdorff_pct,tets,min_dihedral_deg,thinnest_wedge_deg,"
                      "thinnest_border_gap_deg,regions_preserved,features_lost,"
                      "features_lost_larger_than_cell,pockets,pockets_opened,time_read_s,"
                      "time_fake-step_s,time_tetmesh_s,time_write_s,time_picture_s,"
                      "time_total_s,error\n",
                      0),
            0u)
      << csv;
  const json summary = json::parse(read_text(dir / "out/summary.json"));
  EXPECT_EQ(summary.at("runs").size(), 4u);
  EXPECT_EQ(summary.at("runs_failed"), 3);
  EXPECT_EQ(summary.at("runs")[0].at("triangles"), 6786);
  EXPECT_TRUE(summary.at("runs")[1].at("time_tetmesh_s").is_null()) << "skipped steps have no time";
  const std::string html = read_text(dir / "out/report.html");
  EXPECT_NE(html.find("<svg"), std::string::npos);
  EXPECT_NE(html.find("src=\"folded_layers/fail=false/picture.png\""), std::string::npos);
  EXPECT_NE(html.find("asked to fail"), std::string::npos);
  EXPECT_EQ(html.find("<script"), std::string::npos);
}

TEST(RunStudy, AnInvalidVerdictKeepsTheRunGoing) {
  const ModuleRegistry registry = test_registry();
  TempDir dir;
  const Study study = study_from({{"models", test::bundled_model("faulted_layers.ts")},
                                  {"output", dir / "out"},
                                  {"steps", {{{"module", "fake-step"}, {"parameters", {{"verdict", 1}}}},
                                             {{"module", "fake-step"}, {"parameters", {{"value", 2}}}}}},
                                  {"write", {"m.ml"}},
                                  {"picture", false}});
  Logger log(LogLevel::Quiet);
  Progress progress(false);
  const StudyOutcome outcome = run_study(registry, study, {}, log, progress);
  ASSERT_EQ(outcome.runs.size(), 1u);
  const RunOutcome& run = outcome.runs[0];
  EXPECT_EQ(run.status, "invalid");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(run.steps[0].status, "invalid");
  EXPECT_EQ(run.steps[1].status, "ok");
  EXPECT_EQ(run.report.at("fake-step").at("value"), 2.0);
  EXPECT_EQ(run.outputs.size(), 1u);
  EXPECT_TRUE(run.picture.empty());
  EXPECT_EQ(outcome.invalid, 1);
  EXPECT_EQ(outcome.exit_code(), 1);
  EXPECT_EQ(read_model(dir / "out/faulted_layers/default/m.ml").regions.size(), 6u);
}

TEST(RunStudy, RunsAModuleOfThePluginInAPipeline) {
  ModuleRegistry registry = test_registry();
  load_plugin(registry, VOROSEAL_EXAMPLE_PLUGIN);
  TempDir dir;
  const Study study = study_from({{"models", test::bundled_model("folded_layers.ts")},
                                  {"output", dir / "out"},
                                  {"steps", {{{"module", "example-offset"}, {"parameters", {{"dz", {0, 500}}}}}}},
                                  {"write", {"model.obj"}},
                                  {"picture", false}});
  Logger log(LogLevel::Quiet);
  Progress progress(false);
  const StudyOutcome outcome = run_study(registry, study, {}, log, progress);
  ASSERT_EQ(outcome.runs.size(), 2u);
  EXPECT_EQ(outcome.exit_code(), 0);
  auto top = [&](const std::string& key) {
    const StructuralModel m = read_model(dir / ("out/folded_layers/" + key + "/model.obj"));
    return m.bbox().max.z() + m.frame.origin.z();
  };
  EXPECT_NEAR(top("dz=0"), -1000.0, 1e-6);
  EXPECT_NEAR(top("dz=500"), -500.0, 1e-6);
  EXPECT_EQ(outcome.runs[1].report.at("example-offset").at("offset")[2], 500.0);
}

TEST(RunStudy, TheStatsModulesNumbersFillTheRow) {
  Logger log(LogLevel::Quiet);
  Progress progress(false);
  Context context(log, progress);
  context.model = std::make_shared<StructuralModel>(build_model(test::lattice_box(2, true)));
  RunMeasures measured = measure_run(context);
  EXPECT_EQ(measured.row.at("measured_by"), "pipeline");
  EXPECT_EQ(measured.row.at("triangles"), context.model->num_triangles());
  EXPECT_EQ(measured.row.at("regions"), 2);
  EXPECT_NEAR(measured.row.at("area").get<double>(), 7.0, 1e-12);  // 6 faces + the horizon
  EXPECT_NEAR(measured.row.at("bbox_diagonal").get<double>(), std::sqrt(3.0), 1e-12);
  EXPECT_TRUE(measured.row.at("tets").is_null());
  context.report["stats"] = {{"vertices", 5}, {"hausdorff_pct", 0.25}, {"output", {{"min_quality", 0.5}}}};
  measured = measure_run(context);
  EXPECT_EQ(measured.row.at("measured_by"), "stats");
  EXPECT_EQ(measured.row.at("vertices"), 5);
  EXPECT_EQ(measured.row.at("hausdorff_pct"), 0.25);
  EXPECT_EQ(measured.row.at("min_quality"), 0.5);
  EXPECT_EQ(measured.row.at("triangles"), context.model->num_triangles()) << "what stats did not give is measured";
  EXPECT_TRUE(measured.row.at("regions_preserved").is_null());
  context.report["remesh"] = {{"topology",
                               {{"regions_preserved", false},
                                {"features_lost", json::array({json::object(), json::object()})},
                                {"features_lost_larger_than_resolution", 1},
                                {"regions_gained", json::array({json::object()})},
                                {"pockets_removed", json::array({json::object(), json::object(), json::object()})}}}};
  measured = measure_run(context);
  EXPECT_EQ(measured.row.at("regions_preserved"), false);
  EXPECT_EQ(measured.row.at("features_lost"), 2);
  EXPECT_EQ(measured.row.at("features_lost_larger_than_cell"), 1);
  EXPECT_EQ(measured.row.at("pockets"), 1);
  EXPECT_EQ(measured.row.at("pockets_opened"), 3);
}

TEST(RunStudy, BuiltInCheckAndStatsSteps) {
  const ModuleRegistry registry = test_registry();
  if (!registry.find("check") || !registry.find("stats")) GTEST_SKIP() << "check or stats not built in";
  TempDir dir;
  const Study study = study_from({{"models", test::bundled_model("folded_layers.ts")},
                                  {"output", dir / "out"},
                                  {"steps", {"check", "stats"}},
                                  {"picture", false}});
  Logger log(LogLevel::Quiet);
  Progress progress(false);
  const StudyOutcome outcome = run_study(registry, study, {}, log, progress);
  ASSERT_EQ(outcome.runs.size(), 1u);
  const RunOutcome& run = outcome.runs[0];
  EXPECT_EQ(run.status, "ok") << run.error;
  EXPECT_EQ(run.measures.at("measured_by"), "stats");
  EXPECT_EQ(run.measures.at("triangles"), 6786);
  EXPECT_EQ(run.measures.at("surfaces"), 16);
  EXPECT_NEAR(run.measures.at("min_angle_deg").get<double>(), 36.14, 0.01);
}

}  // namespace
}  // namespace voroseal
