#include "io/size_field_format.h"

#include "framework/core/error.h"
#include "io/model_io.h"
#include "io/vtk_format.h"

namespace voroseal {

SizeSamples read_size_field(const TextSource& source) {
  SizeSamples samples;
  LineReader in(source);
  while (in.next_nonblank()) {
    if (in[0].front() == '#') continue;
    if (in.size() != 4)
      in.fail("expected 'x y z h' (4 numbers), found " + std::to_string(in.size()) + " tokens");
    const Vec3 x(in.real(0, "x"), in.real(1, "y"), in.real(2, "z"));
    const double h = in.real(3, "size h");
    if (!(h > 0.0)) in.fail("the size h must be positive, found " + quoted_token(in[3]));
    samples.points.push_back(x);
    samples.sizes.push_back(h);
  }
  if (samples.points.empty())
    throw InputError(source.name(), 0, "a size field needs at least one point 'x y z h'");
  return samples;
}

SizeSamples read_size_field(const std::string& path) {
  const std::string ext = file_extension(path);
  if (ext != ".vtu") return read_size_field(load_text(path));
  // A .vtu: its points, and the point data array of sizes.
  VtuPointField field = read_vtu_point_field(load_text(path));
  for (size_t i = 0; i < field.values.size(); ++i)
    if (!(field.values[i] > 0.0))
      throw InputError(path, field.line,
                       "point data \"" + field.name + "\": the size at point " + std::to_string(i) +
                           " must be positive, found " + std::to_string(field.values[i]));
  if (field.points.empty()) throw InputError(path, 0, "a size field needs at least one point");
  return {std::move(field.points), std::move(field.values)};
}

std::shared_ptr<const SizeField> load_size_field(const std::string& path, const Vec3& origin) {
  SizeSamples samples = read_size_field(path);
  for (Vec3& p : samples.points) p -= origin;
  return std::make_shared<const SizeField>(std::move(samples.points), std::move(samples.sizes));
}

}  // namespace voroseal
