"""Tests of the voroseal Python module (run by ctest with PYTHONPATH=<build>/python)."""
import json
import os
import tempfile
import unittest

import numpy as np

import voroseal

SOURCE = os.environ.get("VOROSEAL_SOURCE_DIR", os.getcwd())
FOLDED = os.path.join(SOURCE, "models", "folded_layers.ts")
FAULTED = os.path.join(SOURCE, "models", "faulted_layers.ts")


def unit_cube():
    """The unit cube, two triangles per face, one group per face (normals outwards)."""
    v = np.array([[x, y, z] for z in (0, 1) for y in (0, 1) for x in (0, 1)], dtype=float)
    quads = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
    tris, groups = [], []
    for g, (a, b, c, d) in enumerate(quads):
        tris += [(a, b, c), (a, c, d)]
        groups += [g, g]
    return v, np.array(tris), np.array(groups)


class ModelTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.model = voroseal.read_model(FOLDED)

    def test_arrays_have_the_documented_shapes_and_counts(self):
        m = self.model
        self.assertEqual(m.vertices.shape, (3293, 3))
        self.assertEqual(m.vertices.dtype, np.float64)
        self.assertEqual(m.triangles.shape, (6786, 3))
        self.assertEqual(m.triangle_parts.shape, (6786,))
        self.assertEqual(m.num_triangles, 6786)
        self.assertEqual(len(m.part_names), 16)
        self.assertEqual(len(m.contacts), 28)
        self.assertEqual(m.corners.shape, (16,))
        self.assertEqual(len(m.regions), 3)
        self.assertEqual(len(m.region_adjacency), 3)
        self.assertEqual(m.part_regions.shape, (16, 2))
        self.assertEqual(set(m.triangle_parts.tolist()), set(range(16)))
        self.assertTrue(0 <= m.triangles.min() and m.triangles.max() < 3293)
        self.assertIn("Model", repr(m))

    def test_coordinates_are_the_files(self):
        lo, hi = self.model.bbox()
        np.testing.assert_allclose(lo, [500000, 4000000, -2000], atol=1e-6)
        np.testing.assert_allclose(hi, [504000, 4003000, -1000], atol=1e-6)
        np.testing.assert_allclose(self.model.vertices.min(axis=0), lo)
        np.testing.assert_allclose(self.model.local_vertices + self.model.origin, self.model.vertices)
        self.assertAlmostEqual(self.model.area / 6.248e7, 1.0, places=3)

    def test_contacts_end_at_corners_and_regions_use_each_side_once(self):
        m = self.model
        corners = set(m.corners.tolist())
        for line, ends in zip(m.contacts, m.contact_corners):
            self.assertGreaterEqual(len(line), 2)
            self.assertIn(line[0], corners)
            self.assertIn(line[-1], corners)
            self.assertEqual(m.corners[ends[0]], line[0])
        sides = [side for region in m.regions for side in region]
        self.assertEqual(len(sides), len(set(sides)))
        for part, positive in sides:
            self.assertTrue(0 <= part < 16 and isinstance(positive, bool))
        # The horizons separate two regions; the box sides have the universe outside.
        for part, (pos, neg) in enumerate(m.part_regions):
            self.assertTrue(pos >= 0 or neg >= 0)
            self.assertNotEqual(pos, neg)
        self.assertEqual([i["kind"] for i in m.interfaces].count("horizon"), 2)

    def test_build_model_from_arrays(self):
        v, t, g = unit_cube()
        m = voroseal.build_model(v, t, g, ["zmin", "zmax", "ymin", "ymax", "xmin", "xmax"])
        self.assertEqual(len(m.part_names), 6)
        self.assertEqual(len(m.contacts), 12)
        self.assertEqual(len(m.corners), 8)
        self.assertEqual(len(m.regions), 1)
        self.assertEqual(sorted(m.regions[0]), [(p, False) for p in range(6)])
        with self.assertRaises(voroseal.ParameterError):
            voroseal.build_model(v, t + 100, g)

    def test_write_and_read_back(self):
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "m.ml")
            self.model.write(path)
            back = voroseal.read_model(path)
            self.assertEqual(back.num_triangles, 6786)
            self.assertEqual(len(back.regions), 3)
            np.testing.assert_allclose(np.sort(back.vertices, axis=0), np.sort(self.model.vertices, axis=0),
                                       atol=1e-6)

    def test_render(self):
        image = self.model.render(width=120, height=90)
        self.assertEqual(image.shape, (90, 120, 3))
        self.assertEqual(image.dtype, np.uint8)
        background = np.all(image == [246, 246, 242], axis=2).mean()
        self.assertLess(background, 0.8)
        with tempfile.TemporaryDirectory() as d:
            self.model.write_picture(os.path.join(d, "p.png"), width=64, height=48)
            with open(os.path.join(d, "p.png"), "rb") as f:
                self.assertEqual(f.read(8), b"\x89PNG\r\n\x1a\n")


class ModuleTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.model = voroseal.read_model(FAULTED)

    def test_modules_come_from_the_registry(self):
        names = [m["name"] for m in voroseal.modules()]
        for name in ("check", "convert", "stats", "tetmesh"):
            self.assertIn(name, names)
        tetmesh = next(m for m in voroseal.modules() if m["name"] == "tetmesh")
        self.assertIn("quality", [p["name"] for p in tetmesh["parameters"]])

    def test_stats_report_is_a_dict_with_the_table_columns(self):
        report = voroseal.run("stats", self.model)
        self.assertEqual(report["triangles"], 6393)
        self.assertEqual(report["surfaces"], 31)
        self.assertEqual(report["regions"], 6)
        self.assertAlmostEqual(report["min_angle_deg"], 31.03, places=2)

    def test_check_gives_a_verdict(self):
        ctx = voroseal.Context(self.model)
        ctx.run("check")
        self.assertEqual(ctx.exit_code, 0)
        self.assertIn("check", ctx.report)

    def test_tetmesh_through_a_context_keeps_the_volume(self):
        ctx = voroseal.Context(self.model)
        report = ctx.run("tetmesh", quality=0)
        volume = ctx.volume
        self.assertEqual(report["tets"], volume.tets.shape[0])
        self.assertEqual(volume.tets.shape[1], 4)
        self.assertEqual(volume.tet_regions.shape, (volume.tets.shape[0],))
        self.assertEqual(len(set(volume.tet_regions.tolist())), 6)
        self.assertEqual(volume.vertices.shape[1], 3)
        self.assertTrue(volume.tets.max() < volume.vertices.shape[0])
        with tempfile.TemporaryDirectory() as d:
            volume.write(os.path.join(d, "v.mesh"))
            back = voroseal.read_volume_mesh(os.path.join(d, "v.mesh"))
            self.assertEqual(back.tets.shape, volume.tets.shape)
        # The caller's model is not changed.
        self.assertEqual(self.model.num_triangles, 6393)

    def test_sizes_per_surface_and_region_are_keyword_parameters(self):
        # Faults finer than the rest, then one region's tets finer: what a study sweeps.
        ctx = voroseal.Context(self.model)
        report = ctx.run("remesh", edge_length=400, size="kind:fault=200")
        sizes = {s["name"]: s for s in report["sizes"]["surfaces"]}
        self.assertEqual(sizes["F1"]["asked"], 200)  # the bundled model's one fault
        self.assertAlmostEqual(sizes["F1"]["realised"], 200, delta=30)
        self.assertGreater(sizes["H1"]["asked"], 300)
        names = ctx.model.region_names
        report = ctx.run("tetmesh", region_size=names[0] + "=300")
        bound = 300 ** 3 / (6 * 2 ** 0.5)
        self.assertAlmostEqual(report["regions"][0]["volume_bound"], bound)
        self.assertLessEqual(report["regions"][0]["largest_tet"], bound * (1 + 1e-9))
        self.assertIsNone(report["regions"][1]["volume_bound"])
        with self.assertRaises(voroseal.ParameterError):
            ctx.run("tetmesh", region_size="no_such_region=300")

    def test_progress_reaches_a_callback_step_by_step(self):
        events = []
        ctx = voroseal.Context(self.model, progress=events.append)
        ctx.run("remesh", seeds=1000, iterations=5)
        steps = [e["step"] for e in events]
        self.assertIn("remesh: optimising seeds", steps)
        # Every step that starts finishes: its last event is its end.
        last = {}
        for e in events:
            last[(e["step"], e["detail"])] = e
        self.assertTrue(all(e["finished"] for e in last.values()))
        for e in events:
            self.assertGreaterEqual(e["seconds"], 0.0)
            if e["total"] > 0:
                self.assertLessEqual(e["done"], e["total"])

    def test_an_exception_in_the_progress_callback_is_raised_after_the_run(self):
        def fail(event):
            raise ValueError("stop here")
        ctx = voroseal.Context(self.model, progress=fail)
        with self.assertRaisesRegex(ValueError, "stop here"):
            ctx.run("remesh", seeds=1000, iterations=3)

    def test_errors_are_python_exceptions(self):
        with self.assertRaises(voroseal.ParameterError):
            voroseal.run("tetmesh", self.model, quality=-1)
        with self.assertRaises(voroseal.ParameterError):
            voroseal.run("tetmesh", self.model, no_such_parameter=1)
        with self.assertRaises(voroseal.ParameterError):
            voroseal.run("no-such-module", self.model)
        with self.assertRaises(voroseal.ModelError):
            voroseal.run("stats")
        with self.assertRaises(voroseal.InputError):
            voroseal.read_model("/nonexistent.ts")
        self.assertTrue(issubclass(voroseal.InputError, voroseal.Error))

    @unittest.skipUnless(os.environ.get("VOROSEAL_EXAMPLE_PLUGIN"), "example plugin not built")
    def test_plugin_modules_run_like_built_in_ones(self):
        loaded = voroseal.load_plugins(os.environ["VOROSEAL_EXAMPLE_PLUGIN"])
        self.assertEqual(loaded["errors"], [])
        ctx = voroseal.Context(self.model)
        report = ctx.run("example-offset", dz=10.0)
        self.assertEqual(report["offset"], [0.0, 0.0, 10.0])
        self.assertAlmostEqual(ctx.model.bbox()[1][2], self.model.bbox()[1][2] + 10.0)


class StudyTest(unittest.TestCase):
    def test_a_study_writes_its_table_and_report(self):
        with tempfile.TemporaryDirectory() as d:
            summary = voroseal.run_study(
                {"name": "py", "models": [FOLDED, os.path.join(d, "missing.ts")],
                 "steps": [{"module": "stats"},
                           {"module": "tetmesh", "parameters": {"quality": [0, 2]}}],
                 "picture": {"width": 160, "height": 110}},
                output=d)
            self.assertEqual(summary["runs_total"], 4)
            self.assertEqual(summary["runs_ok"], 2)
            self.assertEqual(summary["runs_failed"], 2)
            rows = summary["runs"]
            self.assertEqual([r["quality"] for r in rows], [0, 2, 0, 2])
            self.assertEqual(rows[0]["triangles"], 6786)
            self.assertGreater(rows[1]["tets"], 0)
            for f in ("summary.csv", "summary.json", "report.html", "folded_layers/quality=2/picture.png"):
                self.assertTrue(os.path.exists(os.path.join(d, f)), f)
            with open(os.path.join(d, "folded_layers", "quality=0", "run.json")) as f:
                self.assertEqual(json.load(f)["status"], "ok")


if __name__ == "__main__":
    unittest.main()
