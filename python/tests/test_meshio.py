"""Hand-off to meshio and PyVista: Model/VolumeMesh.to_meshio(), from_meshio(), to_pyvista().

Run by ctest with the other test files (PYTHONPATH=<build>/python); skipped without meshio.
"""
import os
import sys
import tempfile
import types
import unittest
from unittest import mock

import numpy as np

import voroseal

try:
    import meshio
except ImportError:
    meshio = None

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.environ.get("VOROSEAL_SOURCE_DIR", os.path.join(HERE, "..", ".."))
FAULTED = os.path.join(SOURCE, "models", "faulted_layers.ts")


def block(mesh, cell_type):
    """Index of the one cell block of `cell_type`."""
    found = [k for k, b in enumerate(mesh.cells) if b.type == cell_type]
    assert len(found) == 1, (cell_type, [b.type for b in mesh.cells])
    return found[0]


def total_volume(vertices, tets):
    """Sum of the tets' unsigned volumes, in a frame near the points (file coordinates are
    large)."""
    p = vertices - vertices.mean(axis=0)
    a, b, c, d = (p[tets[:, k]] for k in range(4))
    return np.abs(np.einsum("ij,ij->i", b - a, np.cross(c - a, d - a))).sum() / 6.0


def two_tets():
    """Two tets sharing the face 1-2-3 (volumes 1/6 and 1/3), positively oriented."""
    v = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 1]], dtype=float)
    return v, np.array([[0, 1, 2, 3], [1, 4, 2, 3]])


def two_tets_surface():
    """The boundary of two_tets() as vertices and triangles (normals outwards)."""
    v, _ = two_tets()
    return v, np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 4], [1, 4, 3], [2, 3, 4]])


@unittest.skipIf(meshio is None, "meshio is not installed")
class ModelToMeshioTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.model = voroseal.read_model(FAULTED)
        cls.mesh = cls.model.to_meshio()

    def test_points_triangles_and_ids_are_the_models(self):
        m, mesh = self.model, self.mesh
        np.testing.assert_array_equal(mesh.points, m.vertices)
        t = block(mesh, "triangle")
        self.assertEqual(len(mesh.cells[t].data), m.num_triangles)
        self.assertEqual(len(mesh.cells[t].data), 6393)
        np.testing.assert_array_equal(mesh.cells[t].data, m.triangles)
        np.testing.assert_array_equal(mesh.cell_data["part"][t], m.triangle_parts)
        np.testing.assert_array_equal(mesh.cell_data["surface"][t],
                                      m.part_interfaces[m.triangle_parts])
        np.testing.assert_array_equal(mesh.cell_data["contact"][t], -1)

    def test_contacts_are_line_cells(self):
        m, mesh = self.model, self.mesh
        e = block(mesh, "line")
        lines = mesh.cells[e].data
        contact = mesh.cell_data["contact"][e]
        self.assertEqual(len(lines), sum(len(c) - 1 for c in m.contacts))
        for c, line in enumerate(m.contacts):
            segments = lines[contact == c]
            np.testing.assert_array_equal(segments[:, 0], line[:-1])
            np.testing.assert_array_equal(segments[:, 1], line[1:])
        np.testing.assert_array_equal(mesh.cell_data["surface"][e], -1)
        np.testing.assert_array_equal(mesh.cell_data["part"][e], -1)

    def test_names_are_field_data(self):
        m, fd = self.model, self.mesh.field_data
        self.assertEqual(len(fd), len(m.interfaces) + len(m.part_names))
        for i, interface in enumerate(m.interfaces):
            self.assertEqual(fd[interface["kind"] + ":" + interface["name"]].tolist(), [i, 2])
        for p, name in enumerate(m.part_names):
            self.assertEqual(fd["part:" + name].tolist(), [p, 2])
        self.assertEqual(fd["fault:F1"].tolist(), [2, 2])

    def test_from_meshio_rebuilds_the_model(self):
        m = self.model
        back = voroseal.from_meshio(self.mesh)
        self.assertIsInstance(back, voroseal.Model)
        self.assertEqual(back.num_triangles, m.num_triangles)
        self.assertEqual(back.part_names, m.part_names)
        self.assertEqual([(i["name"], i["kind"]) for i in back.interfaces],
                         [(i["name"], i["kind"]) for i in m.interfaces])
        self.assertEqual(len(back.regions), len(m.regions))
        self.assertEqual(len(back.regions), 6)
        self.assertEqual(len(back.contacts), len(m.contacts))
        self.assertEqual(len(back.corners), len(m.corners))
        self.assertAlmostEqual(back.area / m.area, 1.0, places=12)

    def test_through_a_file_the_ids_survive_without_names(self):
        # meshio's .vtu writer drops field_data: parts and surfaces come back as part_<id>.
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "model.vtu")
            self.mesh.write(path)
            back = voroseal.from_meshio(meshio.read(path))
        self.assertEqual(back.num_triangles, self.model.num_triangles)
        self.assertEqual(len(back.part_names), len(self.model.part_names))
        self.assertEqual(len(back.interfaces), len(self.model.interfaces))
        self.assertEqual(len(back.regions), len(self.model.regions))
        self.assertEqual(back.part_names[0], "part_0")

    def test_triangles_without_ids_make_one_surface(self):
        v, t = self.model.vertices, self.model.triangles
        back = voroseal.from_meshio(meshio.Mesh(v, [("triangle", t)]))
        self.assertEqual([i["name"] for i in back.interfaces], ["surface_0"])
        self.assertEqual(back.num_triangles, self.model.num_triangles)


@unittest.skipIf(meshio is None, "meshio is not installed")
class VolumeMeshToMeshioTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        ctx = voroseal.Context(voroseal.read_model(FAULTED))
        ctx.run("tetmesh", quality=0)
        cls.volume = ctx.volume
        cls.mesh = cls.volume.to_meshio()

    def test_blocks_and_ids_are_the_volume_meshs(self):
        v, mesh = self.volume, self.mesh
        self.assertEqual([b.type for b in mesh.cells], ["triangle", "tetra", "line", "vertex"])
        np.testing.assert_array_equal(mesh.points, v.vertices)
        t, k, e, c = (block(mesh, name) for name in ("triangle", "tetra", "line", "vertex"))
        np.testing.assert_array_equal(mesh.cells[k].data, v.tets)
        np.testing.assert_array_equal(mesh.cell_data["region"][k], v.tet_regions)
        np.testing.assert_array_equal(mesh.cells[t].data, v.triangles)
        np.testing.assert_array_equal(mesh.cell_data["surface"][t], v.triangle_surfaces)
        np.testing.assert_array_equal(mesh.cell_data["part"][t], v.triangle_parts)
        np.testing.assert_array_equal(mesh.cells[e].data, v.edges)
        np.testing.assert_array_equal(mesh.cell_data["contact"][e], v.edge_contacts)
        np.testing.assert_array_equal(mesh.cells[c].data[:, 0], v.corners)
        np.testing.assert_array_equal(mesh.cell_data["corner"][c], v.corner_ids)
        # -1 where an id does not apply.
        np.testing.assert_array_equal(mesh.cell_data["region"][t], -1)
        np.testing.assert_array_equal(mesh.cell_data["surface"][k], -1)
        for r, name in enumerate(v.region_names):
            self.assertEqual(mesh.field_data["region:" + name].tolist(), [r, 3])
        for s, name in enumerate(v.surface_names):
            self.assertEqual(mesh.field_data[v.surface_kinds[s] + ":" + name].tolist(), [s, 2])

    def test_from_meshio_gives_the_same_mesh_and_names(self):
        v = self.volume
        back = voroseal.from_meshio(self.mesh)
        self.assertIsInstance(back, voroseal.VolumeMesh)
        for name in ("vertices", "tets", "tet_regions", "triangles", "triangle_surfaces",
                     "triangle_parts", "edges", "edge_contacts", "corners", "corner_ids"):
            np.testing.assert_array_equal(getattr(back, name), getattr(v, name), err_msg=name)
        for name in ("region_names", "surface_names", "surface_kinds", "part_names",
                     "contact_names", "corner_names"):
            self.assertEqual(getattr(back, name), getattr(v, name), name)

    def test_round_trip_through_a_vtu_file_written_by_meshio(self):
        v = self.volume
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "volume.vtu")
            self.mesh.write(path)
            read = meshio.read(path)
        back = voroseal.from_meshio(read)
        self.assertEqual(back.tets.shape, v.tets.shape)
        self.assertEqual(back.tets.shape[0], 12510)
        np.testing.assert_array_equal(back.tet_regions, v.tet_regions)
        self.assertEqual(len(set(back.tet_regions.tolist())), 6)
        self.assertEqual(total_volume(back.vertices, back.tets),
                         total_volume(v.vertices, v.tets))
        self.assertAlmostEqual(total_volume(v.vertices, v.tets) / (4000 * 3000 * 1000), 1.0,
                               places=9)
        np.testing.assert_array_equal(back.triangle_surfaces, v.triangle_surfaces)

    def test_a_vtu_file_written_by_voroseal_keeps_the_names_through_meshio(self):
        v = self.volume
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "volume.vtu")
            v.write(path)
            back = voroseal.from_meshio(meshio.read(path))
        np.testing.assert_array_equal(back.tet_regions, v.tet_regions)
        self.assertEqual(back.region_names, v.region_names)
        self.assertEqual(back.surface_kinds, v.surface_kinds)
        self.assertEqual(back.contact_names, v.contact_names)

    def test_gmsh_physical_tags_and_names(self):
        v, t = two_tets()
        mesh = meshio.Mesh(v, [("tetra", t), ("triangle", [[0, 1, 2]])],
                           cell_data={"gmsh:physical": [np.array([3, 5]), np.array([2])]},
                           field_data={"rock": np.array([3, 3]), "clay": np.array([5, 3]),
                                       "fault:F1": np.array([2, 2])})
        back = voroseal.from_meshio(mesh)
        self.assertEqual(back.tet_regions.tolist(), [2, 4])  # tag - 1
        self.assertEqual(back.region_names, ["region_0", "region_1", "rock", "region_3", "clay"])
        self.assertEqual(back.triangle_surfaces.tolist(), [1])
        self.assertEqual(back.surface_names[1], "F1")
        self.assertEqual(back.surface_kinds[1], "fault")

    def test_medit_refs_and_no_ids(self):
        v, t = two_tets()
        back = voroseal.from_meshio(meshio.Mesh(v, [("tetra", t)],
                                                cell_data={"medit:ref": [np.array([1, 2])]}))
        self.assertEqual(back.tet_regions.tolist(), [0, 1])
        back = voroseal.from_meshio(meshio.Mesh(v, [("tetra", t)]))
        self.assertEqual(back.tet_regions.tolist(), [0, 0])
        self.assertEqual(back.region_names, ["region_0"])


class VolumeMeshFromArraysTest(unittest.TestCase):
    def test_arrays_make_a_volume_mesh_in_file_coordinates(self):
        v, t = two_tets()
        v = v + [500000.0, 4000000.0, -1500.0]
        mesh = voroseal.VolumeMesh(v, t, [0, 2], triangles=[[0, 1, 2]], triangle_surfaces=[1],
                                   region_names=["top"], surface_names=["a", "b"],
                                   surface_kinds=["horizon", "fault"], corners=[4])
        np.testing.assert_array_equal(mesh.vertices, v)
        np.testing.assert_array_equal(mesh.tets, t)
        self.assertEqual(mesh.region_names, ["top", "region_1", "region_2"])
        self.assertEqual(mesh.surface_kinds, ["horizon", "fault"])
        self.assertEqual(mesh.corner_ids.tolist(), [0])
        self.assertEqual(mesh.corner_names, ["corner_0"])
        with tempfile.TemporaryDirectory() as d:
            mesh.write(os.path.join(d, "m.vtu"))
            back = voroseal.read_volume_mesh(os.path.join(d, "m.vtu"))
        np.testing.assert_array_equal(back.vertices, v)
        self.assertEqual(back.region_names, mesh.region_names)

    def test_wrong_arrays_are_refused(self):
        v, t = two_tets()
        wrong = [dict(vertices=v, tets=t + 1),                      # vertex 5 does not exist
                 dict(vertices=v, tets=t[:, :3]),                   # not (k, 4)
                 dict(vertices=v, tets=np.zeros((0, 4), int)),      # no tets
                 dict(vertices=v, tets=t.astype(float)),            # floats
                 dict(vertices=v[:, :2], tets=t),                   # 2-d points
                 dict(vertices=v * np.nan, tets=t),                 # not finite
                 dict(vertices=v, tets=t, tet_regions=[0]),         # one id per tet
                 dict(vertices=v, tets=t, tet_regions=[0, -1]),     # negative id
                 dict(vertices=v, tets=t, triangles=[[0, 1, 9]]),
                 dict(vertices=v, tets=t, edges=[[0, 1]], edge_contacts=[0, 1]),
                 dict(vertices=v, tets=t, surface_kinds=["sill"])]
        for arguments in wrong:
            with self.assertRaises(voroseal.ParameterError, msg=str(arguments)):
                voroseal.VolumeMesh(**arguments)


@unittest.skipIf(meshio is None, "meshio is not installed")
class FromMeshioErrorsTest(unittest.TestCase):
    def test_wrong_meshes_raise(self):
        v, t = two_tets()
        with self.assertRaises(TypeError):
            voroseal.from_meshio("mesh.vtu")
        wrong = [meshio.Mesh(v, [("line", [[0, 1]])]),                    # no tets, no triangles
                 meshio.Mesh(v, [("quad", [[0, 1, 4, 2]])]),              # a cell type not read
                 meshio.Mesh(v, [("tetra", t + 1)]),                      # vertex 5
                 meshio.Mesh(v, [("triangle", [[0, 1, 7]])]),
                 meshio.Mesh(v[:, :2], [("tetra", t)]),                   # 2-d points
                 meshio.Mesh(v, [("tetra", t)], cell_data={"region": [np.array([0, -1])]}),
                 meshio.Mesh(v, [("tetra", t)], cell_data={"region": [np.array([0.0, 1.0])]})]
        for mesh in wrong:
            with self.assertRaises(voroseal.ParameterError, msg=str(mesh)):
                voroseal.from_meshio(mesh)
        mesh = meshio.Mesh(v, [("tetra", t)], cell_data={"region": [np.array([0, 1])]})
        mesh.cell_data["region"].append(np.array([0]))  # more arrays than blocks
        with self.assertRaisesRegex(voroseal.ParameterError, "one per block"):
            voroseal.from_meshio(mesh)


class OptionalPackagesTest(unittest.TestCase):
    """meshio and PyVista are imported when called: without them, a clear ImportError."""

    def setUp(self):
        v, t = two_tets()
        self.volume = voroseal.VolumeMesh(v, t, [0, 1], triangles=[[0, 1, 2]],
                                          region_names=["a", "b"], surface_names=["s"])

    def test_without_meshio_an_import_error_says_so(self):
        model = voroseal.build_model(*two_tets_surface())
        with mock.patch.dict(sys.modules, {"meshio": None}):
            with self.assertRaisesRegex(ImportError, "to_meshio.. needs .* 'meshio'"):
                model.to_meshio()
            with self.assertRaisesRegex(ImportError, "to_meshio.. needs .* 'meshio'"):
                self.volume.to_meshio()

    def test_without_pyvista_an_import_error_says_so(self):
        with mock.patch.dict(sys.modules, {"pyvista": None}):
            with self.assertRaisesRegex(ImportError, "to_pyvista.. needs .* 'pyvista'"):
                self.volume.to_pyvista()

    def test_the_grid_gets_vtk_cells_and_ids(self):
        # A stand-in for pyvista (not installed here) that keeps what the grid is made from.
        fake = types.ModuleType("pyvista")

        class UnstructuredGrid:
            def __init__(self, cells, celltypes, points):
                self.cells, self.celltypes, self.points = cells, celltypes, points
                self.cell_data, self.field_data = {}, {}
        fake.UnstructuredGrid = UnstructuredGrid
        with mock.patch.dict(sys.modules, {"pyvista": fake}):
            grid = self.volume.to_pyvista()
        self.assertEqual(grid.celltypes.tolist(), [5, 10, 10])
        self.assertEqual(grid.cells.tolist(), [3, 0, 1, 2, 4, 0, 1, 2, 3, 4, 1, 4, 2, 3])
        np.testing.assert_array_equal(grid.points, self.volume.vertices)
        self.assertEqual(grid.cell_data["region"].tolist(), [-1, 0, 1])
        self.assertEqual(grid.cell_data["surface"].tolist(), [0, -1, -1])
        self.assertEqual(grid.field_data["region:b"].tolist(), [1, 3])
        self.assertEqual(grid.field_data["unknown:s"].tolist(), [0, 2])

    def test_with_pyvista(self):
        try:
            import pyvista
        except ImportError:
            self.skipTest("pyvista is not installed")
        grid = self.volume.to_pyvista()
        self.assertIsInstance(grid, pyvista.UnstructuredGrid)
        self.assertEqual(grid.n_cells, 3)
        self.assertEqual(list(grid.cell_data["region"]), [-1, 0, 1])
        self.assertAlmostEqual(grid.volume, 0.5)
        model = voroseal.build_model(*two_tets_surface())
        self.assertEqual(model.to_pyvista().n_cells, model.num_triangles
                         + sum(len(c) - 1 for c in model.contacts))


if __name__ == "__main__":
    unittest.main()
