// A size field: edge lengths asked at points of space (`--size-field FILE`). At a point x of
// the surfaces the size is the smallest h_i + slope · |x − p_i| over the field's points near x:
// h at the points, growing away from them as fast as the gradation lets sizes grow. A well path
// sampled with the size wanted around it gives cells of that size along the well and graded
// ones around it; a dense field is followed to within slope × its spacing.
#pragma once

#include <memory>
#include <vector>

#include "framework/core/types.h"

namespace voroseal {

class SizeField {
 public:
  /// `points` in the model's local frame, `sizes` positive, one per point (at least one).
  SizeField(std::vector<Vec3> points, std::vector<double> sizes);
  ~SizeField();
  SizeField(SizeField&&) noexcept;
  SizeField& operator=(SizeField&&) noexcept;

  /// A field whose size is the smaller of `a`'s and `b`'s (either may be null; null when both
  /// are): two sources of sizes, each followed on its own. points() and sizes() are `a`'s.
  static std::shared_ptr<const SizeField> smallest(std::shared_ptr<const SizeField> a,
                                                   std::shared_ptr<const SizeField> b);

  /// The size at x for sizes growing by `slope` per unit length (gradation − 1), from the
  /// kNearest points closest to x (and the smaller one of the field joined by smallest()).
  double size_at(const Vec3& x, double slope) const;
  /// Index of the field's point nearest to x.
  int nearest(const Vec3& x) const;

  const std::vector<Vec3>& points() const { return points_; }
  const std::vector<double>& sizes() const { return sizes_; }

  static constexpr int kNearest = 16;

 private:
  struct Tree;
  std::vector<Vec3> points_;
  std::vector<double> sizes_;
  std::unique_ptr<Tree> tree_;
  std::shared_ptr<const SizeField> also_;  // joined by smallest(), or null
};

}  // namespace voroseal
