#include "framework/geometry/size_field.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "framework/core/error.h"
#include "framework/geometry/point_cloud.h"

namespace voroseal {

struct SizeField::Tree {
  PointCloud cloud;
  std::unique_ptr<PointKdTree> index;
};

SizeField::SizeField(std::vector<Vec3> points, std::vector<double> sizes)
    : points_(std::move(points)), sizes_(std::move(sizes)), tree_(std::make_unique<Tree>()) {
  if (points_.empty() || points_.size() != sizes_.size())
    throw ParameterError("a size field needs as many sizes as points, and at least one");
  for (double h : sizes_)
    if (!(h > 0.0) || !std::isfinite(h))
      throw ParameterError("the sizes of a size field must be positive and finite");
  tree_->cloud.points = points_.data();
  tree_->cloud.count = points_.size();
  tree_->index =
      std::make_unique<PointKdTree>(3, tree_->cloud, nanoflann::KDTreeSingleIndexAdaptorParams(12));
  tree_->index->buildIndex();
}

SizeField::~SizeField() = default;
SizeField::SizeField(SizeField&&) noexcept = default;
SizeField& SizeField::operator=(SizeField&&) noexcept = default;

std::shared_ptr<const SizeField> SizeField::smallest(std::shared_ptr<const SizeField> a,
                                                     std::shared_ptr<const SizeField> b) {
  if (a == nullptr) return b;
  if (b == nullptr) return a;
  auto joined = std::make_shared<SizeField>(a->points_, a->sizes_);
  joined->also_ = a->also_ == nullptr ? std::move(b) : smallest(a->also_, std::move(b));
  return joined;
}

double SizeField::size_at(const Vec3& x, double slope) const {
  const size_t k = std::min<size_t>(kNearest, points_.size());
  std::uint32_t index[kNearest];
  double distance2[kNearest];
  const size_t found = tree_->index->knnSearch(x.data(), k, index, distance2);
  double best = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < found; ++i)
    best = std::min(best, sizes_[index[i]] + slope * std::sqrt(distance2[i]));
  return also_ == nullptr ? best : std::min(best, also_->size_at(x, slope));
}

int SizeField::nearest(const Vec3& x) const {
  std::uint32_t index = 0;
  double distance2 = 0.0;
  tree_->index->knnSearch(x.data(), 1, &index, &distance2);
  return static_cast<int>(index);
}

}  // namespace voroseal
