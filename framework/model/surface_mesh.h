// The triangle mesh of one surface part: an OpenMesh TriMesh with double precision points.
#pragma once

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

namespace voroseal {

struct SurfaceMeshTraits : public OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};

using SurfaceMesh = OpenMesh::TriMesh_ArrayKernelT<SurfaceMeshTraits>;

}  // namespace voroseal
