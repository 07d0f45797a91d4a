"""Bad problems raise InputError with the library's JSON path and formula
column; the classes, and their pickling (batches send them back)."""

import pickle

import pytest

import intercurve as ic
from conftest import example

BOX = [[-2, 2], [-2, 2], [-2, 2]]


def problem(f_b):
    return {"surfaces": [{"type": "implicit", "f": "x^2 + y^2 - 1"},
                         {"type": "implicit", "f": f_b}], "box": BOX}


@pytest.mark.parametrize("formula, fault", [
    ("z - 0.5 * (x + )", ")"),
    ("z - foo(x)", "foo"),
    ("z - x $ 2", "$"),
])
def test_formula_error_has_path_and_column(formula, fault):
    with pytest.raises(ic.InputError) as e:
        ic.Problem.from_dict(problem(formula))
    assert e.value.path == "surfaces[1].f"
    assert e.value.column == formula.index(fault) + 1  # 1-based
    assert e.value.code == 2 and e.value.status == "parse error"
    assert "surfaces[1].f: column %d: " % e.value.column in str(e.value)


def test_invalid_value_has_path():
    with pytest.raises(ic.InputError) as e:
        ic.Problem.from_dict({"surfaces": [{"type": "sphere", "radius": -1},
                                           {"type": "implicit", "f": "z"}]})
    assert e.value.path == "surfaces[0]" and e.value.column == 0
    assert "radius" in e.value.message


def test_one_surface_is_an_input_error():
    with pytest.raises(ic.InputError) as e:
        ic.Problem.from_json('{"surfaces": [{"type": "implicit", "f": "z"}]}')
    assert e.value.path == "surfaces"


def test_malformed_json_and_missing_file(tmp_path):
    with pytest.raises(ic.InputError):
        ic.Problem.from_json('{"surfaces": [')
    with pytest.raises(ic.InputError, match="cannot open"):
        ic.Problem.load(tmp_path / "missing.json")
    with pytest.raises(ic.InputError, match="not JSON"):
        ic.Problem.from_dict({"surfaces": {1, 2}})


def test_error_classes():
    assert issubclass(ic.InputError, ValueError) and issubclass(ic.InputError, ic.Error)
    assert issubclass(ic.ComputationError, RuntimeError)
    e = ic.InputError("msg", 2, "parse error", "surfaces[0].f", 7)
    back = pickle.loads(pickle.dumps(e))
    assert type(back) is ic.InputError
    assert (back.message, back.code, back.status, back.path, back.column) == (
        "msg", 2, "parse error", "surfaces[0].f", 7)


def test_problem_pickles_and_keeps_its_title():
    for p in (ic.Problem.load(example("cusp.json")), ic.Problem.from_dict(problem("z"))):
        back = pickle.loads(pickle.dumps(p))
        assert back.title == p.title and back.surface_names == p.surface_names


def test_library_is_the_build_or_the_one_named():
    import os
    path = ic.library_path()
    assert os.path.basename(path).startswith("libintercurve.so")
    if os.environ.get("INTERCURVE_LIB"):
        assert path == os.environ["INTERCURVE_LIB"]
