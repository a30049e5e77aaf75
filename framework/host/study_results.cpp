#include "framework/host/study_results.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>

#include "framework/core/error.h"

namespace voroseal {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr const char* kRunFile = "run.json";

// A path relative to `from` (the output folder a run was written to) made relative to `to`.
std::string rebase(const std::string& path, const fs::path& from, const fs::path& to) {
  if (path.empty() || from == to) return path;
  return (from / path).lexically_normal().lexically_relative(to).generic_string();
}

std::string text_or_empty(const json& value) {
  return value.is_string() ? value.get<std::string>() : std::string();
}

std::optional<json> read_json(const std::string& path) {
  std::ifstream in(path);
  if (!in) return std::nullopt;
  try {
    return json::parse(in);
  } catch (const json::parse_error&) {
    return std::nullopt;
  }
}

// The study key where two study documents differ first, for the error message.
std::string first_difference(const json& a, const json& b) {
  for (const auto& [key, value] : a.items())
    if (!b.contains(key) || b[key] != value) return key;
  for (const auto& [key, value] : b.items())
    if (!a.contains(key)) return key;
  return "";
}

fs::path absolute_folder(const std::string& folder) {
  return fs::absolute(folder).lexically_normal();
}

}  // namespace

RunOutcome run_outcome_from_json(const json& document, const StudyRun& run,
                                 const std::string& output, const std::string& file) {
  RunOutcome outcome;
  outcome.run = run;
  // The files a run lists are relative to the output folder it was written to, which holds
  // <model>/<key>/run.json.
  const fs::path written_to = absolute_folder(run.directory).parent_path().parent_path();
  const fs::path target = absolute_folder(output);
  try {
    outcome.status = document.at("status").get<std::string>();
    outcome.exit_code = document.at("exit_code").get<int>();
    outcome.error = text_or_empty(document.at("error"));
    for (const json& s : document.at("steps")) {
      StepOutcome step;
      step.module = s.at("module").get<std::string>();
      step.status = s.at("status").get<std::string>();
      step.exit_code = s.at("exit_code").get<int>();
      step.seconds = s.at("seconds").get<double>();
      step.error = text_or_empty(s.value("error", json()));
      step.text = rebase(text_or_empty(s.value("text", json())), written_to, target);
      outcome.steps.push_back(step);
    }
    const json& seconds = document.at("seconds");
    outcome.read_seconds = seconds.at("read").get<double>();
    outcome.write_seconds = seconds.at("write").get<double>();
    outcome.picture_seconds = seconds.at("picture").get<double>();
    outcome.total_seconds = seconds.at("total").get<double>();
    outcome.parameters = document.at("parameters");
    outcome.report = document.at("report");
    outcome.measures = document.at("measures");
    outcome.histograms = document.at("histograms");
    outcome.legend = document.at("legend");
    for (const json& o : document.at("outputs"))
      outcome.outputs.push_back(rebase(o.get<std::string>(), written_to, target));
    outcome.picture = rebase(text_or_empty(document.at("picture")), written_to, target);
    // Absent from the run.json files of versions without the picture of the tets.
    outcome.cut_picture =
        rebase(text_or_empty(document.value("cut_picture", json())), written_to, target);
    outcome.region_legend = document.value("region_legend", json::array());
  } catch (const json::exception& e) {
    throw InputError(file, 0, std::string("not a voroseal run.json: ") + e.what());
  }
  return outcome;
}

std::optional<RunOutcome> read_complete_run(const Study& study, const StudyRun& run) {
  const std::string file = (fs::path(run.directory) / kRunFile).string();
  const std::optional<json> document = read_json(file);
  if (!document || !document->is_object()) return std::nullopt;
  const json& d = *document;
  if (d.value("definition", json()) != study_document(study) || d.value("run", -1) != run.index ||
      d.value("key", "") != run.key || d.value("model_label", "") != run.model_label)
    return std::nullopt;
  const std::string status = d.value("status", "");
  if (status != "ok" && status != "invalid") return std::nullopt;
  RunOutcome outcome;
  try {
    outcome = run_outcome_from_json(d, run, study.output, file);
  } catch (const InputError&) {
    return std::nullopt;
  }
  std::vector<std::string> files = outcome.outputs;
  if (!outcome.picture.empty()) files.push_back(outcome.picture);
  if (!outcome.cut_picture.empty()) files.push_back(outcome.cut_picture);
  for (const std::string& f : files) {
    std::error_code error;
    if (!fs::is_regular_file(fs::path(study.output) / f, error)) return std::nullopt;
  }
  return outcome;
}

MergedStudy merge_study_results(const std::vector<std::string>& folders,
                                const std::string& output) {
  // Every <model>/<key>/run.json, in a fixed order.
  std::vector<std::string> files;
  for (const std::string& folder : folders) {
    std::error_code error;
    if (!fs::is_directory(folder, error)) throw InputError(folder, 0, "not a folder");
    std::vector<std::string> here;
    for (const auto& model : fs::directory_iterator(folder, error)) {
      if (!model.is_directory()) continue;
      for (const auto& key : fs::directory_iterator(model.path(), error))
        if (key.is_directory() && fs::is_regular_file(key.path() / kRunFile))
          here.push_back((key.path() / kRunFile).string());
    }
    if (error) throw InputError(folder, 0, "cannot list: " + error.message());
    std::sort(here.begin(), here.end());
    files.insert(files.end(), here.begin(), here.end());
  }
  std::string listed;
  for (const std::string& f : folders) listed += (listed.empty() ? "" : ", ") + f;
  if (files.empty()) throw ParameterError("--merge: no run.json found in " + listed);

  std::vector<json> documents;
  for (const std::string& file : files) {
    std::optional<json> d = read_json(file);
    if (!d || !d->is_object()) throw InputError(file, 0, "cannot read this run.json");
    if (!d->contains("definition"))
      throw InputError(file, 0, "records no study definition (run it again with this voroseal)");
    documents.push_back(std::move(*d));
  }

  // The study, as its runs recorded it; all of them must record the same.
  const json& definition = documents[0]["definition"];
  for (size_t i = 1; i < documents.size(); ++i)
    if (documents[i]["definition"] != definition)
      throw ParameterError("--merge: " + files[i] + " is a run of another study than " + files[0] +
                           " (they differ in \"" +
                           first_difference(definition, documents[i]["definition"]) + "\")");
  const std::string study_file = text_or_empty(documents[0].value("study_file", json()));
  Study study = parse_study(definition, "", study_file);
  if (!output.empty()) study.output = absolute_folder(output).string();
  const std::vector<StudyRun> runs = expand_study(study);

  MergedStudy merged;
  merged.outcome.study = study;
  std::map<int, size_t> found;  // run index -> position in files
  for (size_t i = 0; i < files.size(); ++i) {
    const json& d = documents[i];
    const int index = d.value("run", -1);
    if (index < 0 || index >= static_cast<int>(runs.size()) ||
        d.value("key", "") != runs[index].key ||
        d.value("model_label", "") != runs[index].model_label)
      throw ParameterError("--merge: " + files[i] + " is no run of study " + study.name +
                           " (its run number, model or key does not match)");
    if (found.count(index))
      throw ParameterError("--merge: run " + std::to_string(index + 1) + " found twice: " +
                           (files[found[index]] == files[i]
                                ? files[i] + " (a folder given twice)"
                                : files[found[index]] + " and " + files[i]));
    found[index] = i;
  }
  for (const StudyRun& run : runs) {
    const auto at = found.find(run.index);
    if (at == found.end()) {
      merged.missing.push_back(run.index + 1);
      continue;
    }
    StudyRun here = run;
    here.directory = absolute_folder(files[at->second]).parent_path().string();
    merged.outcome.runs.push_back(
        run_outcome_from_json(documents[at->second], here, study.output, files[at->second]));
    const RunOutcome& r = merged.outcome.runs.back();
    merged.outcome.failed += r.status == "failed" ? 1 : 0;
    merged.outcome.invalid += r.status == "invalid" ? 1 : 0;
    merged.outcome.seconds += r.total_seconds;
  }
  return merged;
}

}  // namespace voroseal
