"""The option table walked through Python: every option is a keyword argument of Tracker and
TrackerOptions and a property of TrackerOptions, and every bad value is refused with the message
the CLI and config files give (tests/cli_options_test.cc walks those)."""

import math
import pathlib
import pydoc

import numpy as np
import pytest

import scbt
from conftest import pentagon, render

TABLE = scbt.option_table()
NAMES = [row["name"] for row in TABLE]


def number(x):
    """A number as the table's messages write it (C's %.10g)."""
    return "nan" if math.isnan(x) else f"{x:.10g}"


def other_value(row):
    """A valid value other than the default."""
    default = row["default"]
    if row["type"] == "bool":
        return not default
    if row["type"] == "choice":
        return row["choices"][1] if default == row["choices"][0] else row["choices"][0]
    if row["type"] == "int":
        return default - 1 if default == row["max"] else default + 1
    return default + 0.25 if default + 0.25 < row["max"] else default - 0.25


def range_words(row):
    if math.isinf(row["min"]) or math.isinf(row["max"]):
        return row["range"]  # "<= 10000"
    return "in " + row["range"]


def bad_values(row):
    """(value, exception, message) the table refuses."""
    name = row["name"]
    expected = f"{name} must be {row['expected']}, got "
    if row["type"] == "bool":
        return [(2, ValueError, expected + "2"), ("maybe", TypeError, expected + "'maybe'")]
    if row["type"] == "choice":
        return [("nosuch", ValueError, expected + "'nosuch'"), (7, TypeError, expected + "7")]
    out_of_range = f"{name} must be {range_words(row)}, got "
    bad = [("abc", TypeError, expected + "'abc'"), (math.nan, ValueError, out_of_range + "nan")]
    if not math.isinf(row["min"]):
        low = row["min"] - (0 if row["min_open"] else 1)
        bad.append((low, ValueError, out_of_range + number(low)))
    if not math.isinf(row["max"]):
        high = row["max"] + (0 if row["max_open"] else 1)
        bad.append((high, ValueError, out_of_range + number(high)))
    if row["type"] == "int":
        bad.append((2.5, ValueError, expected + "2.5"))
        bad = [(int(v) if isinstance(v, float) and v.is_integer() else v, e, m) for v, e, m in bad]
    return bad


def test_table_is_small_and_matches_the_class():
    assert 10 <= len(TABLE) <= 16
    assert scbt.TrackerOptions().keys() == NAMES
    assert list(scbt.TrackerOptions().as_dict()) == NAMES
    for row in TABLE:
        assert row["flag"] == "--" + row["name"].replace("_", "-")
        assert getattr(scbt.TrackerOptions(), row["name"]) == row["default"]
        assert row["help"] and row["group"]


@pytest.mark.parametrize("row", TABLE, ids=NAMES)
def test_every_option_is_accepted_everywhere(row, tmp_path):
    name, value = row["name"], other_value(row)
    assert value != row["default"]
    options = scbt.TrackerOptions(**{name: value})
    assert getattr(options, name) == value and options[name] == value
    assert f"{name}={value!r}" in repr(options)
    assert scbt.Tracker(**{name: value}).options == options
    assert scbt.Tracker(options).options[name] == value
    changed = scbt.TrackerOptions()
    setattr(changed, name, value)
    assert changed == options
    # The config-file text round-trips through a file, YAML and JSON.
    for json in (False, True):
        path = tmp_path / ("options.json" if json else "options.yaml")
        path.write_text(options.to_text(json=json))
        assert scbt.TrackerOptions.from_file(str(path)) == options


@pytest.mark.parametrize("row", TABLE, ids=NAMES)
def test_every_bad_value_is_refused_with_the_tables_message(row):
    name = row["name"]
    for value, error, message in bad_values(row):
        for make in (scbt.TrackerOptions, scbt.Tracker):
            with pytest.raises(error) as info:
                make(**{name: value})
            assert str(info.value) == message, (make, value)
        options = scbt.TrackerOptions()
        with pytest.raises(error) as info:
            setattr(options, name, value)
        assert str(info.value) == message
        assert options == scbt.TrackerOptions()  # left as it was


def test_keywords_override_the_options_object():
    base = scbt.TrackerOptions(shape_weight=2.0, seed_stride=3)
    tracker = scbt.Tracker(base, shape_weight=1.0, keep_debug=True)
    assert tracker.options.shape_weight == 1.0 and tracker.options.seed_stride == 3
    assert tracker.keep_debug is True
    assert base.shape_weight == 2.0


def test_unknown_and_internal_options_are_refused():
    with pytest.raises(TypeError, match="unexpected keyword argument 'sigma'"):
        scbt.Tracker(sigma=1.5)
    with pytest.raises(TypeError, match="unexpected keyword argument 'cost_tolerance'"):
        scbt.TrackerOptions(cost_tolerance=0.0)
    with pytest.raises(TypeError, match="must be a TrackerOptions"):
        scbt.Tracker({"shape_weight": 2.0})


def test_config_file_errors_name_the_file(tmp_path):
    path = tmp_path / "bad.yaml"
    path.write_text("shape_weight: 101\n")
    with pytest.raises(ValueError, match=r"bad\.yaml: shape_weight must be in \[0, 100\], got 101"):
        scbt.TrackerOptions.from_file(str(path))


def test_help_lists_every_option():
    text = pydoc.render_doc(scbt.TrackerOptions, renderer=pydoc.plaintext)
    for row in TABLE:
        assert row["name"] in text and row["help"][:30] in text
    tracker_help = pydoc.render_doc(scbt.Tracker, renderer=pydoc.plaintext)
    for method in ("init(", "update(", "track(", "box_or_polygon"):
        assert method in tracker_help


def test_init_takes_a_box_or_a_polygon():
    truth = pentagon((160, 120), 50)
    frame = render(truth)
    from_polygon = scbt.Tracker().init(frame, truth)
    np.testing.assert_allclose(from_polygon, truth)
    xs, ys = truth[:, 0], truth[:, 1]
    box = (xs.min() - 10, ys.min() - 10, np.ptp(xs) + 20, np.ptp(ys) + 20)
    tracker = scbt.Tracker()
    from_box = tracker.init(frame, box)
    assert from_box.shape[1] == 2 and len(from_box) >= 3
    assert scbt.shape_distance(from_box, truth) < 0.1
    ok, boundary = tracker.update(frame)
    assert ok is True
    assert boundary.shape[1] == 2 and scbt.shape_distance(boundary, truth) < 0.1


def test_update_reports_a_lost_object():
    truth = pentagon((160, 120), 50)
    tracker = scbt.Tracker()
    tracker.init(render(truth), truth)
    empty = np.full((240, 320), 128, np.uint8)
    results = [tracker.update(empty) for _ in range(6)]
    assert results[-1][0] is False
    assert all(b.shape[1] == 2 for _, b in results)


def test_polygons_round_trip_through_a_file(tmp_path):
    first = pentagon((160, 120), 50)
    second = first + 3.5
    path = tmp_path / "results.txt"
    scbt.write_polygons(str(path), [first, second])
    assert path.read_text().count("\n") == 2
    read = scbt.read_polygons(str(path))
    assert len(read) == 2
    np.testing.assert_allclose(read[0], first, atol=0.005)
    np.testing.assert_allclose(read[1], second, atol=0.005)
    path.write_text("3 0 0 10 0 10 10\n3 0 0 x 0 5 5\n")
    with pytest.raises(ValueError, match=r"results\.txt:2:"):
        scbt.read_polygons(str(path))
    with pytest.raises(ValueError, match="cannot open"):
        scbt.read_polygons(str(tmp_path / "missing.txt"))


def test_stub_and_docs_list_every_option():
    root = pathlib.Path(__file__).resolve().parents[2]
    stub = (root / "python" / "scbt.pyi").read_text()
    cli_doc = (root / "docs" / "cli.md").read_text()
    python_doc = (root / "docs" / "python.md").read_text()
    for row in TABLE:
        name = row["name"]
        assert stub.count(f"        {name}: ") == 2, name  # TrackerOptions and Tracker
        assert f"    {name}: " in stub, name  # the property
        default = row["default"]
        shown = default if isinstance(default, str) else number(default)
        if isinstance(default, bool):
            shown = str(default).lower()
        assert f"| `{row['flag']}` | {shown} | {row['range']} |" in cli_doc, row["flag"]
        assert f"| `{name}` |" in python_doc, name
