#include "framework/host/study_shard.h"

#include <cctype>

#include "framework/core/error.h"

namespace voroseal {

namespace {

// A positive decimal integer, or -1 when the text is not one (or too large for an int).
int positive_integer(const std::string& text) {
  if (text.empty() || text.size() > 9) return -1;
  for (char c : text)
    if (!std::isdigit(static_cast<unsigned char>(c))) return -1;
  const int value = std::stoi(text);
  return value > 0 ? value : -1;
}

}  // namespace

StudyShard parse_shard(const std::string& text) {
  const size_t slash = text.find('/');
  const int index = slash == std::string::npos ? -1 : positive_integer(text.substr(0, slash));
  const int count = slash == std::string::npos ? -1 : positive_integer(text.substr(slash + 1));
  if (index < 1 || count < 1 || index > count)
    throw ParameterError("--shard: expected I/N with 1 <= I <= N (shard I of N), got '" + text +
                         "'");
  return {index, count};
}

std::vector<int> shard_runs(const std::vector<StudyRun>& runs, const StudyShard& shard) {
  std::vector<int> selected;
  for (const StudyRun& run : runs)
    if (run.index % shard.count == shard.index - 1) selected.push_back(run.index);
  return selected;
}

}  // namespace voroseal
