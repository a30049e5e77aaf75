// Defects a remesh inherits from an input that `check` finds invalid: a set of fault surfaces
// from a community fault model that cross without contacts, bound no region and end in free
// borders. Such an input can still be remeshed; the remesh is then judged against it: what the
// input has too is a warning, what the remesh made is still an error.
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "framework/model/structural_model.h"
#include "modules/check/model_validity.h"

namespace voroseal {

/// The input's failed error checks that a remesh of it fails by construction.
class InputDefects {
 public:
  /// From the input and `check`'s verdict on it. The crossings are found here, where their
  /// places are kept: the verdict need not have tested them (CheckOptions::intersections).
  InputDefects(const StructuralModel& input, const ValidityReport& verdict);
  ~InputDefects();
  InputDefects(const InputDefects&) = delete;
  InputDefects& operator=(const InputDefects&) = delete;

  bool any() const { return !failed_.empty(); }
  /// Names of the input's failed checks a remesh inherits (free borders, no bounded region,
  /// region orientation, self-intersections).
  const std::vector<std::string>& failed() const { return failed_; }
  long crossings() const { return crossings_; }
  /// The pairs of input parts (a < b, sorted, unique) that cross in the input.
  std::vector<std::pair<int, int>> crossing_parts() const;

  /// Turns the failed error checks of `verdict` (on `output`, a remesh of the input whose parts
  /// map to input parts by `input_part_of_output`) that the input fails too into warnings. A
  /// crossing of two output parts is inherited when their input parts cross within `reach` of
  /// it (the cell size, plus the input triangles' own size); the others stay errors, with their
  /// places.
  void excuse(const StructuralModel& output, const std::vector<int>& input_part_of_output,
              double reach, ValidityReport& verdict) const;

 private:
  struct Crossings;
  std::vector<std::string> failed_;
  long crossings_ = 0;
  std::unique_ptr<Crossings> where_;  // the input's crossings, by pair of parts
};

}  // namespace voroseal
