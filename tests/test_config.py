"""Tests for simulator.config.loader: loading, validation messages, grids, overrides."""

from __future__ import annotations

import math
import textwrap
from pathlib import Path

import numpy as np
import pytest

from simulator.config.loader import (
    DEFAULT_MAX_SAMPLES,
    DEVICES,
    METHODS,
    GridConfig,
    RunConfig,
    SensorKind,
    apply_overrides,
    load_config,
)
from simulator.errors import UserError

STAGE_LINE = 'stage = "stage.usda"\n'


@pytest.fixture
def write(tmp_path):
    """Write a config (and an empty stage.usda beside it); return its path."""
    (tmp_path / "stage.usda").write_text("#usda 1.0\n")

    def _write(body: str, name: str = "run.toml", stage: bool = True) -> Path:
        p = tmp_path / name
        p.write_text((STAGE_LINE if stage else "") + textwrap.dedent(body))
        return p

    return _write


def load_error(path) -> str:
    """Load a config expected to fail; return the message after checking it is one line."""
    with pytest.raises(UserError) as info:
        load_config(path)
    msg = str(info.value)
    assert "\n" not in msg, msg
    assert msg.startswith(str(path) + ": "), msg
    return msg


# --------------------------------------------------------------------------- defaults


def test_defaults(write, tmp_path):
    """A config with only `stage` gets every documented default and absolute paths."""
    p = write("")
    cfg = load_config(p)
    assert isinstance(cfg, RunConfig)
    assert cfg.path == p.resolve() and cfg.path.is_absolute()
    assert cfg.stage == (tmp_path / "stage.usda").resolve()
    assert cfg.light_units == "photometric"
    assert cfg.radiometric_spectrum == "E"
    sim = cfg.simulation
    assert (sim.samples, sim.seed, sim.method, sim.device) == (1024, 1, "auto", "cpu")
    assert sim.rel_error is None and sim.max_samples is None and sim.time_limit_s is None
    assert sim.abs_error == 0.0 and sim.max_depth == -1 and sim.threads == 0
    assert not sim.adaptive and sim.sample_cap == DEFAULT_MAX_SAMPLES == 2**20
    assert cfg.sensors == [] and cfg.grids == []
    assert cfg.output.csv == (tmp_path / "run.csv").resolve()
    assert cfg.raw == {"stage": "stage.usda"}
    assert cfg.overrides == {}


def test_full_simulation_and_paths(write, tmp_path):
    """Every [simulation] key is read; ints are accepted for floats; stage and csv resolve against the config folder."""
    (tmp_path / "stages").mkdir()
    (tmp_path / "stages" / "q.usda").write_text("")
    (tmp_path / "configs").mkdir()
    p = tmp_path / "configs" / "a.toml"
    p.write_text(
        textwrap.dedent(
            """\
            stage = "../stages/q.usda"
            light_units = "radiometric"
            radiometric_spectrum = "D65"
            [simulation]
            samples = 64
            seed = 0
            method = "mis"
            device = "auto"
            rel_error = 0.05
            abs_error = 1
            max_samples = 4096
            time_limit_s = 5
            max_depth = 3
            threads = 2
            [output]
            csv = "../out/q.csv"
            """
        )
    )
    cfg = load_config(p)
    assert cfg.stage == (tmp_path / "stages" / "q.usda").resolve()
    assert cfg.output.csv == (tmp_path / "out" / "q.csv").resolve()
    assert cfg.light_units == "radiometric" and cfg.radiometric_spectrum == "D65"
    sim = cfg.simulation
    assert (sim.samples, sim.seed, sim.method, sim.device) == (64, 0, "mis", "auto")
    assert sim.rel_error == 0.05 and sim.adaptive
    assert sim.abs_error == 1.0 and isinstance(sim.abs_error, float)
    assert sim.max_samples == 4096 and sim.sample_cap == 4096
    assert sim.time_limit_s == 5.0 and isinstance(sim.time_limit_s, float)
    assert sim.max_depth == 3 and sim.threads == 2


def test_sensors_of_each_kind(write):
    """Irradiance, radiance and patch sensors become Sensor records: float64 arrays, unit normals, radians, sources and default names."""
    p = write(
        """
        [[sensor]]
        name = "desk"
        kind = "irradiance"
        position = [1, 2, 0.75]
        normal = [0, 0, 5]

        [[sensor]]
        kind = "radiance"
        position = [0, 0, 1]
        direction = [3, 0, -4]
        half_angle_deg = 30

        [[sensor]]
        name = "window"
        kind = "patch"
        position = [0, 0, 0]
        normal = [0, 0, 2]
        size = [2, 1.5]
        up = [0, 3, 0]
        """
    )
    cfg = load_config(p)
    a, b, c = cfg.sensors
    assert a.name == "desk" and a.kind == SensorKind.IRRADIANCE and a.source == "sensor[0]"
    assert a.position.dtype == np.float64 and a.normal.dtype == np.float64
    np.testing.assert_array_equal(a.position, [1, 2, 0.75])
    np.testing.assert_allclose(a.normal, [0, 0, 1])
    assert a.grid is None
    assert b.name == "sensor[1]" and b.kind == SensorKind.RADIANCE and b.source == "sensor[1]"
    np.testing.assert_allclose(b.normal, [0.6, 0, -0.8])
    assert b.half_angle == pytest.approx(math.pi / 6)
    assert c.kind == SensorKind.PATCH and c.size == (2.0, 1.5)
    np.testing.assert_allclose(c.normal, [0, 0, 1])
    np.testing.assert_allclose(c.up, [0, 1, 0])


def test_radiance_half_angle_default(write):
    """A radiance sensor without half_angle_deg has half_angle 0 (one direction)."""
    p = write(
        """
        [[sensor]]
        kind = "radiance"
        position = [0, 0, 1]
        direction = [0, 0, -1]
        """
    )
    assert load_config(p).sensors[0].half_angle == 0.0


def test_patch_up_orthogonalised(write):
    """A patch `up` not orthogonal to `normal` is made orthogonal (Gram–Schmidt) and normalised."""
    p = write(
        """
        [[sensor]]
        kind = "patch"
        position = [0, 0, 0]
        normal = [0, 0, 1]
        size = [1, 1]
        up = [0, 1, 1]
        """
    )
    s = load_config(p).sensors[0]
    np.testing.assert_allclose(s.up, [0, 1, 0], atol=1e-15)
    assert abs(float(np.dot(s.up, s.normal))) < 1e-15
    assert float(np.linalg.norm(s.up)) == pytest.approx(1.0)


def test_patch_up_orthogonalised_tilted(write):
    """For a tilted normal the orthogonalised up is unit, orthogonal to normal, and in the plane of normal and the given up."""
    p = write(
        """
        [[sensor]]
        kind = "patch"
        position = [0, 0, 0]
        normal = [1, 0, 1]
        size = [1, 1]
        up = [0, 0, 1]
        """
    )
    s = load_config(p).sensors[0]
    n = np.array([1, 0, 1]) / math.sqrt(2)
    np.testing.assert_allclose(s.up, [-1 / math.sqrt(2), 0, 1 / math.sqrt(2)], atol=1e-12)
    assert abs(float(np.dot(s.up, n))) < 1e-12


# --------------------------------------------------------------------------- grids


def test_grid_expansion(write):
    """A 2 m x 1 m grid at spacing 0.5 gives 4 x 2 irradiance cells named floor[i,j] at cell centres that tile the rectangle; right = +X for normal +Z, up +Y."""
    p = write(
        """
        [[sensor]]
        name = "desk"
        kind = "irradiance"
        position = [0, 0, 1]
        normal = [0, 0, 1]

        [[grid]]
        name = "floor"
        position = [10, 20, 0]
        normal = [0, 0, 1]
        size = [2, 1]
        up = [0, 1, 0]
        spacing = 0.5
        """
    )
    cfg = load_config(p)
    assert [s.name for s in cfg.sensors][:2] == ["desk", "floor[0,0]"]
    cells = cfg.sensors[1:]
    assert len(cells) == 8
    (g,) = cfg.grids
    assert isinstance(g, GridConfig)
    assert (g.name, g.nx, g.ny, g.source) == ("floor", 4, 2, "grid[0]")
    np.testing.assert_allclose(g.right, [1, 0, 0])
    np.testing.assert_allclose(g.up, [0, 1, 0])
    np.testing.assert_allclose(g.normal, [0, 0, 1])
    np.testing.assert_array_equal(g.centre, [10, 20, 0])
    assert g.cell_size == (0.5, 0.5)
    assert g.sensor_names == tuple(s.name for s in cells)
    by_name = {s.name: s for s in cells}
    assert set(by_name) == {f"floor[{i},{j}]" for i in range(4) for j in range(2)}
    for s in cells:
        assert s.kind == SensorKind.IRRADIANCE and s.grid == "floor" and s.source == "grid[0]"
        np.testing.assert_allclose(s.normal, [0, 0, 1])
    np.testing.assert_allclose(by_name["floor[0,0]"].position, [9.25, 19.75, 0])
    np.testing.assert_allclose(by_name["floor[3,1]"].position, [10.75, 20.25, 0])
    np.testing.assert_allclose(by_name["floor[2,0]"].position, g.cell_centre(2, 0))
    xs = sorted({float(s.position[0]) for s in cells})
    ys = sorted({float(s.position[1]) for s in cells})
    np.testing.assert_allclose(xs, [9.25, 9.75, 10.25, 10.75])
    np.testing.assert_allclose(ys, [19.75, 20.25])
    # the cells tile the rectangle: mean of centres is the centre, extent = size - cell
    np.testing.assert_allclose(np.mean([s.position for s in cells], axis=0), [10, 20, 0])


def test_grid_spacing_pair_and_rounding(write):
    """spacing = [sx, sy] sets cells per axis as max(1, round(w/sx)), max(1, round(h/sy)); cells are w/nx wide, so they tile exactly."""
    p = write(
        """
        [[grid]]
        name = "wall"
        position = [0, 0, 0]
        normal = [0, 0, 1]
        size = [1.0, 0.3]
        up = [0, 1, 0]
        spacing = [0.3, 1.0]
        """
    )
    cfg = load_config(p)
    (g,) = cfg.grids
    assert (g.nx, g.ny) == (3, 1)  # round(3.33) = 3; round(0.3) = 0 -> 1
    assert g.spacing == (0.3, 1.0)
    assert g.cell_size == pytest.approx((1 / 3, 0.3))
    xs = sorted(float(s.position[0]) for s in cfg.sensors)
    np.testing.assert_allclose(xs, [-1 / 3, 0, 1 / 3], atol=1e-12)
    assert all(float(s.position[1]) == pytest.approx(0.0) for s in cfg.sensors)


def test_grid_axes_vertical_wall(write):
    """For normal -Y and up +Z the width axis is normalize(cross(up, normal)) = +X; j runs along +Z."""
    p = write(
        """
        [[grid]]
        name = "wall"
        position = [0, 5, 1]
        normal = [0, -1, 0]
        size = [2, 2]
        up = [0, 0, 1]
        spacing = 1
        """
    )
    cfg = load_config(p)
    (g,) = cfg.grids
    np.testing.assert_allclose(g.right, [1, 0, 0])
    by_name = {s.name: s for s in cfg.sensors}
    np.testing.assert_allclose(by_name["wall[1,0]"].position, [0.5, 5, 0.5])
    np.testing.assert_allclose(by_name["wall[0,1]"].position, [-0.5, 5, 1.5])


def test_two_grids_in_file_order(write):
    """Grid cells follow config sensors, grid by grid in file order, each with its own source."""
    p = write(
        """
        [[grid]]
        name = "a"
        position = [0, 0, 0]
        normal = [0, 0, 1]
        size = [1, 1]
        up = [0, 1, 0]
        spacing = 1
        [[grid]]
        name = "b"
        position = [0, 0, 1]
        normal = [0, 0, 1]
        size = [2, 1]
        up = [0, 1, 0]
        spacing = 1
        """
    )
    cfg = load_config(p)
    assert [s.name for s in cfg.sensors] == ["a[0,0]", "b[0,0]", "b[1,0]"]
    assert [s.source for s in cfg.sensors] == ["grid[0]", "grid[1]", "grid[1]"]


# --------------------------------------------------------------------------- file-level errors


def test_missing_config_file(tmp_path):
    """A config file that does not exist is a one-line UserError naming the file."""
    p = tmp_path / "nope.toml"
    msg = load_error(p)
    assert "not found" in msg


def test_invalid_toml(write):
    """Invalid TOML is a one-line UserError naming the file and carrying tomllib's message (with its line number)."""
    p = write("[simulation\nsamples = 3\n")
    msg = load_error(p)
    assert "invalid TOML" in msg and "line" in msg


def test_missing_stage_file(write, tmp_path):
    """A stage path that does not exist is an error on `stage` naming the resolved path."""
    p = write('stage = "../stages/missing.usda"\n', stage=False)
    msg = load_error(p)
    assert ": stage: " in msg
    assert str((tmp_path.parent / "stages" / "missing.usda").resolve()) in msg


def test_missing_stage_key(write):
    """A config without `stage` is an error naming the key."""
    msg = load_error(write("light_units = 'photometric'\n", stage=False))
    assert ": stage: required" in msg


# --------------------------------------------------------------------------- unknown keys


def test_unknown_top_level_key(write):
    """An unknown top-level key is an error naming it and listing the allowed keys."""
    msg = load_error(write("stagee = 'x'\n"))
    assert ": stagee: unknown key" in msg and "stage" in msg


def test_unknown_simulation_key(write):
    """An unknown key in [simulation] is an error on simulation.<key> that lists the expected keys and suggests the near one."""
    msg = load_error(write("[simulation]\nsamplez = 3\n"))
    assert ": simulation.samplez: unknown key" in msg
    assert "'samples'" in msg and "expected one of: samples, seed" in msg


def test_unknown_sensor_key(write):
    """An unknown key in a [[sensor]] is an error on sensor[i].<key>."""
    msg = load_error(
        write(
            """
            [[sensor]]
            kind = "irradiance"
            position = [0, 0, 0]
            normal = [0, 0, 1]
            [[sensor]]
            kind = "irradiance"
            position = [0, 0, 0]
            normal = [0, 0, 1]
            colour = "red"
            """
        )
    )
    assert ": sensor[1].colour: unknown key" in msg


def test_unknown_grid_and_output_keys(write):
    """Unknown keys in [[grid]] and [output] are errors naming grid[i].<key> and output.<key>."""
    msg = load_error(
        write(
            """
            [[grid]]
            name = "g"
            position = [0, 0, 0]
            normal = [0, 0, 1]
            size = [1, 1]
            up = [0, 1, 0]
            spacing = 1
            step = 2
            """
        )
    )
    assert ": grid[0].step: unknown key" in msg
    msg = load_error(write("[output]\njson = 'a.json'\n", name="o.toml"))
    assert ": output.json: unknown key" in msg


def test_key_not_valid_for_kind(write):
    """A key that belongs to another sensor kind (direction on irradiance) is an error naming the key and the kind."""
    msg = load_error(
        write(
            """
            [[sensor]]
            kind = "irradiance"
            position = [0, 0, 0]
            normal = [0, 0, 1]
            direction = [0, 0, -1]
            """
        )
    )
    assert ": sensor[0].direction: not valid for kind 'irradiance'" in msg


def test_half_angle_on_patch_not_valid(write):
    """half_angle_deg on a patch sensor is an error naming the key."""
    msg = load_error(
        write(
            """
            [[sensor]]
            kind = "patch"
            position = [0, 0, 0]
            normal = [0, 0, 1]
            size = [1, 1]
            up = [0, 1, 0]
            half_angle_deg = 10
            """
        )
    )
    assert ": sensor[0].half_angle_deg: not valid for kind 'patch'" in msg


# --------------------------------------------------------------------------- types and values


def test_string_where_number(write):
    """A string where an integer is expected is an error naming the key and the expected type."""
    msg = load_error(write("[simulation]\nsamples = '1024'\n"))
    assert ": simulation.samples: expected an integer, got string" in msg


def test_bool_where_number(write):
    """A boolean is never accepted as a number, neither for ints nor floats."""
    msg = load_error(write("[simulation]\nseed = true\n"))
    assert ": simulation.seed: expected an integer, got boolean" in msg
    msg = load_error(write("[simulation]\nabs_error = false\n", name="b.toml"))
    assert ": simulation.abs_error: expected a number, got boolean" in msg


def test_string_in_vector(write):
    """A string inside a position is an error naming the element."""
    msg = load_error(
        write(
            """
            [[sensor]]
            kind = "irradiance"
            position = [0, "1", 0]
            normal = [0, 0, 1]
            """
        )
    )
    assert ": sensor[0].position[1]: expected a number, got string" in msg


def test_float_where_int(write):
    """A float where an integer is expected (samples = 10.0) is an error."""
    msg = load_error(write("[simulation]\nsamples = 10.0\n"))
    assert ": simulation.samples: expected an integer, got float" in msg


def test_wrong_vector_length(write):
    """A normal with 2 components is an error naming the key."""
    msg = load_error(
        write(
            """
            [[sensor]]
            kind = "irradiance"
            position = [0, 0, 0]
            normal = [0, 1]
            """
        )
    )
    assert ": sensor[0].normal: expected an array of 3 numbers" in msg


def test_zero_length_normal(write):
    """A zero normal is 'zero-length vector' on sensor[i].normal."""
    msg = load_error(
        write(
            """
            [[sensor]]
            kind = "irradiance"
            position = [0, 0, 0]
            normal = [0, 0, 0]
            """
        )
    )
    assert msg.endswith(": sensor[0].normal: zero-length vector")


def test_zero_length_direction(write):
    """A zero radiance direction is an error on sensor[i].direction."""
    msg = load_error(
        write(
            """
            [[sensor]]
            kind = "radiance"
            position = [0, 0, 0]
            direction = [0, 0.0, 0]
            """
        )
    )
    assert ": sensor[0].direction: zero-length vector" in msg


@pytest.mark.parametrize("bad", ["nan", "inf", "-inf"])
def test_non_finite_position(write, bad):
    """TOML nan/inf in a position is an error naming the element: positions must be finite."""
    msg = load_error(
        write(
            f"""
            [[sensor]]
            kind = "irradiance"
            position = [0, {bad}, 0]
            normal = [0, 0, 1]
            """
        )
    )
    assert ": sensor[0].position[1]: must be a finite number" in msg


def test_non_finite_float_setting(write):
    """nan for a float setting (rel_error) is an error."""
    msg = load_error(write("[simulation]\nrel_error = nan\n"))
    assert ": simulation.rel_error: must be a finite number" in msg


def test_unknown_sensor_kind(write):
    """An unknown kind is an error on sensor[i].kind listing the kinds."""
    msg = load_error(
        write(
            """
            [[sensor]]
            kind = "thermometer"
            position = [0, 0, 0]
            """
        )
    )
    assert ": sensor[0].kind: unknown sensor kind 'thermometer'" in msg
    assert "irradiance, radiance, patch, probe" in msg


def test_missing_sensor_kind(write):
    """A sensor without kind is an error on sensor[i].kind."""
    msg = load_error(write("[[sensor]]\nposition = [0, 0, 0]\n"))
    assert ": sensor[0].kind: required key is missing" in msg


def test_missing_required_sensor_key(write):
    """A patch without size is an error on sensor[i].size."""
    msg = load_error(
        write(
            """
            [[sensor]]
            kind = "patch"
            position = [0, 0, 0]
            normal = [0, 0, 1]
            up = [0, 1, 0]
            """
        )
    )
    assert ": sensor[0].size: required key is missing" in msg


def test_unknown_method(write):
    """An unknown method is an error on simulation.method listing the methods."""
    msg = load_error(write("[simulation]\nmethod = 'raytrace'\n"))
    assert ": simulation.method: unknown method 'raytrace'" in msg
    assert ", ".join(METHODS) in msg


def test_unknown_device_and_units(write):
    """Unknown device, light_units and radiometric_spectrum values are errors naming their keys."""
    assert ": simulation.device: unknown device 'gpu'" in load_error(write("[simulation]\ndevice = 'gpu'\n"))
    assert ": light_units: unknown" in load_error(write("light_units = 'lux'\n", name="u.toml"))
    assert ": radiometric_spectrum: unknown" in load_error(write("radiometric_spectrum = 'A'\n", name="s.toml"))


@pytest.mark.parametrize(
    "line, key",
    [
        ("samples = 0", "simulation.samples"),
        ("seed = -1", "simulation.seed"),
        ("seed = 2147483648", "simulation.seed"),
        ("rel_error = 1.0", "simulation.rel_error"),
        ("rel_error = 0", "simulation.rel_error"),
        ("abs_error = -0.1", "simulation.abs_error"),
        ("max_samples = 0", "simulation.max_samples"),
        ("time_limit_s = 0", "simulation.time_limit_s"),
        ("max_depth = -2", "simulation.max_depth"),
        ("threads = -1", "simulation.threads"),
    ],
)
def test_simulation_out_of_range(write, line, key):
    """Each [simulation] value outside its documented range is an error naming its key."""
    msg = load_error(write(f"[simulation]\n{line}\n"))
    assert f": {key}: must be" in msg


def test_simulation_not_a_table(write):
    """`simulation = 3` is an error: expected a table."""
    msg = load_error(write("simulation = 3\n"))
    assert ": simulation: expected a table, got integer" in msg


def test_sensor_not_array_of_tables(write):
    """[sensor] written as a single table instead of [[sensor]] is an error on `sensor`."""
    msg = load_error(write("[sensor]\nkind = 'irradiance'\n"))
    assert ": sensor: expected an array of tables" in msg


@pytest.mark.parametrize("angle", [90, -1, 120.5])
def test_half_angle_out_of_range(write, angle):
    """half_angle_deg outside [0, 90) is an error on sensor[i].half_angle_deg."""
    msg = load_error(
        write(
            f"""
            [[sensor]]
            kind = "radiance"
            position = [0, 0, 0]
            direction = [0, 0, -1]
            half_angle_deg = {angle}
            """
        )
    )
    assert ": sensor[0].half_angle_deg: must be >= 0 and < 90" in msg


def test_patch_size_not_positive(write):
    """A patch size with a zero side is an error naming the element."""
    msg = load_error(
        write(
            """
            [[sensor]]
            kind = "patch"
            position = [0, 0, 0]
            normal = [0, 0, 1]
            size = [1, 0]
            up = [0, 1, 0]
            """
        )
    )
    assert ": sensor[0].size[1]: must be > 0" in msg


def test_patch_up_parallel_to_normal(write):
    """A patch up parallel (or anti-parallel) to its normal is an error on sensor[i].up."""
    msg = load_error(
        write(
            """
            [[sensor]]
            kind = "patch"
            position = [0, 0, 0]
            normal = [0, 0, 1]
            size = [1, 1]
            up = [0, 0, -2]
            """
        )
    )
    assert ": sensor[0].up: parallel to sensor[0].normal" in msg


def test_grid_up_parallel_to_normal(write):
    """A grid up parallel to its normal is an error on grid[i].up."""
    msg = load_error(
        write(
            """
            [[grid]]
            name = "g"
            position = [0, 0, 0]
            normal = [1, 1, 0]
            size = [1, 1]
            up = [2, 2, 0]
            spacing = 1
            """
        )
    )
    assert ": grid[0].up: parallel to grid[0].normal" in msg


def test_grid_bad_spacing(write):
    """A grid spacing that is zero, negative, a string or the wrong length is an error on grid[i].spacing."""
    base = """
        [[grid]]
        name = "g"
        position = [0, 0, 0]
        normal = [0, 0, 1]
        size = [1, 1]
        up = [0, 1, 0]
        """
    assert ": grid[0].spacing: must be > 0" in load_error(write(base + "spacing = 0\n", name="a.toml"))
    assert ": grid[0].spacing: expected a number or an array" in load_error(
        write(base + "spacing = '1'\n", name="b.toml")
    )
    assert ": grid[0].spacing[0]: must be > 0" in load_error(write(base + "spacing = [-1, 1]\n", name="c.toml"))
    assert ": grid[0].spacing: expected an array of 2 numbers" in load_error(
        write(base + "spacing = [1, 1, 1]\n", name="d.toml")
    )


def test_grid_name_required(write):
    """A grid without a name is an error on grid[i].name."""
    msg = load_error(
        write(
            """
            [[grid]]
            position = [0, 0, 0]
            normal = [0, 0, 1]
            size = [1, 1]
            up = [0, 1, 0]
            spacing = 1
            """
        )
    )
    assert ": grid[0].name: required key is missing" in msg


# --------------------------------------------------------------------------- names


def test_duplicate_sensor_names(write):
    """Two sensors with the same name is an error on the second one's name, naming the first."""
    msg = load_error(
        write(
            """
            [[sensor]]
            name = "desk"
            kind = "irradiance"
            position = [0, 0, 0]
            normal = [0, 0, 1]
            [[sensor]]
            name = "desk"
            kind = "radiance"
            position = [0, 0, 0]
            direction = [0, 0, 1]
            """
        )
    )
    assert ": sensor[1].name: duplicate sensor name 'desk' (also sensor[0])" in msg


def test_explicit_name_clashes_with_default(write):
    """An explicit name equal to another sensor's default name ('sensor[0]') is a duplicate."""
    msg = load_error(
        write(
            """
            [[sensor]]
            kind = "irradiance"
            position = [0, 0, 0]
            normal = [0, 0, 1]
            [[sensor]]
            name = "sensor[0]"
            kind = "irradiance"
            position = [0, 0, 0]
            normal = [0, 0, 1]
            """
        )
    )
    assert ": sensor[1].name: duplicate sensor name 'sensor[0]'" in msg


def test_grid_cell_name_clashes_with_sensor(write):
    """A grid cell name equal to a config sensor's name is an error on the grid's name."""
    msg = load_error(
        write(
            """
            [[sensor]]
            name = "g[0,0]"
            kind = "irradiance"
            position = [0, 0, 0]
            normal = [0, 0, 1]
            [[grid]]
            name = "g"
            position = [0, 0, 0]
            normal = [0, 0, 1]
            size = [1, 1]
            up = [0, 1, 0]
            spacing = 1
            """
        )
    )
    assert ": grid[0].name: cell sensor name 'g[0,0]' is already used by sensor[0]" in msg


def test_duplicate_grid_names(write):
    """Two grids with the same name is an error on the second grid's name."""
    grid = """
        [[grid]]
        name = "g"
        position = [0, 0, 0]
        normal = [0, 0, 1]
        size = [1, 1]
        up = [0, 1, 0]
        spacing = 1
        """
    msg = load_error(write(grid + grid))
    assert ": grid[1].name: duplicate grid name 'g' (also grid[0])" in msg


def test_first_problem_reported(write):
    """With several problems the first in file order is reported (the top-level key before the sensor)."""
    msg = load_error(
        write(
            """
            bogus = 1
            [[sensor]]
            kind = "irradiance"
            position = [0, 0, 0]
            normal = [0, 0, 0]
            """
        )
    )
    assert ": bogus: unknown key" in msg and "sensor[0]" not in msg


# --------------------------------------------------------------------------- overrides


def test_overrides_applied(write, tmp_path, monkeypatch):
    """apply_overrides returns a new config with the flags applied, csv resolved against the current directory, and records them; the original is unchanged."""
    p = write("[simulation]\nsamples = 8\nseed = 3\n[output]\ncsv = 'x.csv'\n")
    cfg = load_config(p)
    cwd = tmp_path / "elsewhere"
    cwd.mkdir()
    monkeypatch.chdir(cwd)
    new = apply_overrides(cfg, seed=7, samples=99, device="cuda", csv="out/r.csv", method="path")
    assert new is not cfg
    sim = new.simulation
    assert (sim.seed, sim.samples, sim.device, sim.method) == (7, 99, "cuda", "path")
    assert new.output.csv == (cwd / "out" / "r.csv").resolve()
    assert new.overrides["seed"] == 7 and new.overrides["csv"] == str(new.output.csv)
    assert (cfg.simulation.seed, cfg.simulation.samples) == (3, 8)
    assert cfg.output.csv == (tmp_path / "x.csv").resolve()
    assert new.sensors == cfg.sensors and new.raw == cfg.raw


def test_overrides_none_keeps_config(write):
    """apply_overrides with no flags keeps every value."""
    cfg = load_config(write("[simulation]\nsamples = 8\n"))
    new = apply_overrides(cfg)
    assert new.simulation == cfg.simulation and new.output == cfg.output and new.overrides == {}


@pytest.mark.parametrize(
    "kwargs, flag",
    [
        ({"samples": 0}, "--samples"),
        ({"samples": True}, "--samples"),
        ({"seed": -1}, "--seed"),
        ({"seed": 2**31}, "--seed"),
        ({"device": "gpu"}, "--device"),
        ({"method": "magic"}, "--method"),
        ({"csv": ""}, "--csv"),
    ],
)
def test_overrides_validated(write, kwargs, flag):
    """Invalid flag values are one-line UserErrors naming the flag."""
    cfg = load_config(write(""))
    with pytest.raises(UserError) as info:
        apply_overrides(cfg, **kwargs)
    msg = str(info.value)
    assert msg.startswith(flag + ": ") and "\n" not in msg


def test_constants():
    """METHODS and DEVICES are the documented tuples."""
    assert METHODS == ("auto", "analytic", "exact", "light", "bsdf", "mis", "path", "guided")
    assert DEVICES == ("cpu", "cuda", "auto")


def test_confidence_key_and_flag(write):
    """`confidence` is a probability in (0.5, 1), in the config and as a flag."""
    cfg = load_config(write("[simulation]\nconfidence = 0.999\n"))
    assert cfg.simulation.confidence == 0.999
    assert load_config(write("")).simulation.confidence == 0.95
    msg = load_error(write("[simulation]\nconfidence = 95\n"))
    assert "simulation.confidence: must be between 0.5 and 1" in msg
    with pytest.raises(UserError, match="--confidence"):
        apply_overrides(cfg, confidence=1.0)


# --------------------------------------------------------------------------- schema


def test_sensor_kind_models_cover_the_kinds():
    """Each sensor kind has one schema model, keyed and tagged by its config name, building that kind."""
    from simulator.config.sensors import SENSOR_ENTRIES, SENSOR_KEYS
    from simulator.scene.model import SENSOR_KINDS

    assert list(SENSOR_ENTRIES) == list(SENSOR_KINDS)
    for name, model in SENSOR_ENTRIES.items():
        assert model.KIND == SENSOR_KINDS[name]
        assert list(model.model_fields)[:3] == ["name", "kind", "position"]
    assert SENSOR_KEYS == ("name", "kind", "position", "normal", "model", "gain", "integration_ms", "azimuth_ref", "direction",
                           "half_angle_deg", "size", "up", "resolution", "axis", "facing", "evalglare", "dgp_stderr")


@pytest.mark.parametrize(
    "flag, kwargs, line",
    [
        ("--samples", {"samples": 0}, "samples = 0"),
        ("--samples", {"samples": True}, "samples = true"),
        ("--seed", {"seed": 2**31}, "seed = 2147483648"),
        ("--method", {"method": "magic"}, "method = 'magic'"),
        ("--device", {"device": "gpu"}, "device = 'gpu'"),
        ("--rel-error", {"rel_error": 1.0}, "rel_error = 1.0"),
        ("--rel-error", {"rel_error": math.nan}, "rel_error = nan"),
        ("--confidence", {"confidence": 0.3}, "confidence = 0.3"),
    ],
)
def test_flag_and_key_share_one_rule(write, flag, kwargs, line):
    """A flag is checked by its [simulation] key's rule: the same value gives the same message, naming the flag instead of the key."""
    key = "simulation." + next(iter(kwargs))
    from_file = load_error(write(f"[simulation]\n{line}\n", name="bad.toml"))
    with pytest.raises(UserError) as info:
        apply_overrides(load_config(write("")), **kwargs)
    assert from_file.split(f": {key}: ", 1)[1] == str(info.value).split(f"{flag}: ", 1)[1]


def test_flags_recorded_in_flag_order(write):
    """Valid flags replace their keys, leave the others as the file gave them, and are recorded as applied."""
    cfg = load_config(write("[simulation]\nsamples = 8\nmax_depth = 3\n"))
    new = apply_overrides(cfg, confidence=0.99, rel_error=0.25, seed=0)
    sim = new.simulation
    assert (sim.seed, sim.rel_error, sim.confidence) == (0, 0.25, 0.99) and sim.adaptive
    assert (sim.samples, sim.max_depth) == (8, 3)
    assert list(new.overrides.items()) == [("seed", 0), ("rel_error", 0.25), ("confidence", 0.99)]


@pytest.mark.parametrize(
    "item, words",
    [("reflectance", "expected SET=VARIANT or /PRIM/PATH:SET=VARIANT, got 'reflectance'"), ("=rho_0_9", "empty variant set name"),
     ("reflectance= ", "empty variant name")],
)  # fmt: skip
def test_variant_flag_checked(write, item, words):
    """--variant must be SET=VARIANT; blank names break the `variants` table's own rule, named as the flag."""
    with pytest.raises(UserError) as info:
        apply_overrides(load_config(write("")), variants=[item])
    assert str(info.value) == f"--variant: {words}"


def test_variant_flag_overrides_the_table(write):
    """--variant adds to the config's variants and replaces the same set (names stripped)."""
    cfg = load_config(write('variants = { reflectance = "rho_0_5", look = "dark" }\n'))
    new = apply_overrides(cfg, variants=[" reflectance = rho_0_9"])
    assert new.variants == {"reflectance": "rho_0_9", "look": "dark"}
    assert new.overrides == {"variants": [" reflectance = rho_0_9"]}
    assert cfg.variants["reflectance"] == "rho_0_5"


def test_close_match_suggested_in_a_sensor(write):
    """A misspelt sensor key names the key and suggests the near one among all sensor keys."""
    msg = load_error(
        write(
            """
            [[sensor]]
            kind = "irradiance"
            position = [0, 0, 0]
            normall = [0, 0, 1]
            """
        )
    )
    assert ": sensor[0].normall: unknown key (did you mean 'normal'?" in msg


def test_first_problem_in_file_order(write):
    """Within a table the first bad value in file order is the one reported."""
    msg = load_error(write("[simulation]\nseed = -1\nsamples = 0\n"))
    assert msg.endswith(": simulation.seed: must be >= 0, got -1")


def test_messages_name_units(write):
    """A radiance cone's bound is stated in degrees."""
    msg = load_error(
        write(
            """
            [[sensor]]
            kind = "radiance"
            position = [0, 0, 0]
            direction = [0, 0, -1]
            half_angle_deg = 95
            """
        )
    )
    assert msg.endswith(": sensor[0].half_angle_deg: must be >= 0 and < 90 degrees, got 95")


def test_integers_for_numbers_everywhere(write):
    """Integers are taken for every number (vectors, sizes, angles, spacing) and come out as floats."""
    cfg = load_config(
        write(
            """
            [[sensor]]
            kind = "radiance"
            position = [1, 2, 3]
            direction = [0, 0, -2]
            half_angle_deg = 30
            [[grid]]
            name = "g"
            position = [0, 0, 0]
            normal = [0, 0, 1]
            size = [2, 1]
            up = [0, 1, 0]
            spacing = 1
            """
        )
    )
    s = cfg.sensors[0]
    assert s.position.dtype == np.float64 and s.half_angle == pytest.approx(math.pi / 6)
    (g,) = cfg.grids
    assert g.size == (2.0, 1.0) and g.spacing == (1.0, 1.0)
    assert all(isinstance(x, float) for x in g.size + g.spacing)


def test_error_naming_key_in_a_grid_array(write):
    """A [[grid]] entry that is not a table is an error on grid[i]."""
    msg = load_error(write("grid = [1]\n"))
    assert msg.endswith(": grid[0]: expected a table ([[grid]]), got integer")
