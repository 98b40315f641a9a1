"""Python's keywords are checked by the option table (renderer/app/option_specs.h), as the command line's
options are: each is refused just beyond its range, in the same words, naming the keyword."""
import re

import pytest

import glossy
from conftest import material_path

SPECS = glossy._core._option_specs()


def beyond(spec):
    """Values just outside the range, as the message shows them."""
    if spec["whole"]:
        hi, lo = int(spec["hi"]) + 1, int(spec["lo"]) - 1
        return [(hi, str(hi)), (lo, str(lo))]
    hi, lo = spec["hi"] * 2 + 1, spec["lo"] if spec["lo_open"] else spec["lo"] - 1
    return [(hi, f"{hi:g}"), (lo, f"{lo:g}")]


def call(spec, value):
    key, of = spec["keyword"], spec["commands"]
    if key in ("width", "height"):  # Python's size=(width, height)
        size = (value, 8) if key == "width" else (8, value)
        return (glossy.render if of.startswith("render") else lambda **a: glossy.sheet(material=material_path("chrome"), **a))(size=size)
    if of.startswith("render"):
        return glossy.render(**{key: value})
    if of.startswith("sheet"):
        return glossy.sheet(material=material_path("chrome"), **{key: value})
    if of.startswith("fit"):
        table = glossy.load_merl(material_path("chrome").with_suffix(".nbrdf"))
        return glossy.fit(table, **{key: value})
    return glossy.uniforms(**{key: value})


@pytest.mark.parametrize("spec", SPECS, ids=[f"{s['keyword']}-{s['commands'].split(',')[0]}" for s in SPECS])
def test_each_keyword_is_refused_beyond_its_range_in_the_tables_words(spec):
    name = spec["keyword"] if spec["keyword"] not in ("width", "height") else "size: " + spec["keyword"]
    kind = "whole" if spec["whole"] else "finite"
    for value, shown in beyond(spec):
        with pytest.raises(glossy.InputError, match="^" + re.escape(f"{name}: must be a {kind} number in {spec['range']}, not '{shown}'") + "$"):
            call(spec, value)


def test_the_documented_defaults_are_the_tables():
    """The signatures' defaults in the type stubs are the table's."""
    stubs = (glossy.__path__[0] + "/__init__.pyi")
    text = open(stubs).read()
    for spec in SPECS:
        if spec["keyword"] in ("threads", "max_depth", "light_samples", "seed", "starts", "max_iterations"):
            assert re.search(rf"\b{spec['keyword']}: int = {int(spec['default'])}\b", text), spec["keyword"]
