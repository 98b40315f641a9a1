"""glossy: analytic and measured BRDFs, their fitting and their rendering, on NumPy arrays.

The models of Löw et al. 2012 (microfacet, smooth, ABC/AS, Cook-Torrance) as the paper writes them, MERL
measured data, the metrics E1 and E2 with the fitter, and the path tracer with its comparison sheets:
the numbers and images of the `glossy` command, from Python. docs/python.md walks through an example.

    import glossy
    table = glossy.load_merl("materials/library/merl/alum-bronze.nbrdf")   # or a MERL NAME.binary(.xz)
    fit = glossy.fit(table, model="cook-torrance", metric="E2")
    image = glossy.render(brdf=fit.brdf, spp=16, size=256)
"""
from pathlib import Path as _Path

import numpy as _np

from . import _core
from ._core import *  # noqa: F403 (the compiled module's public names, which __all__ lists)
from ._core import __version__

# pybind11 before 2.12 reads NumPy 1's array descriptors; NumPy 2 laid them out anew.
if _core._pybind11_version < (2, 12) and int(_np.__version__.split(".")[0]) >= 2:
    raise ImportError(f"glossy was built with pybind11 {'.'.join(map(str, _core._pybind11_version))}, which needs "
                      f"NumPy 1 (found {_np.__version__}): use Debian's python3-numpy, or `pip install .`")

# A wheel carries the default scene and the material library; a build tree uses its source tree's.
if (_Path(__file__).parent / "data" / "scenes").is_dir():
    _core._set_data_dir(str(_Path(__file__).parent / "data"))

from ._study import Study, read_study, study  # noqa: E402 (after the NumPy check above)

__all__ = sorted(["__version__", "Study", "read_study", "study"] + [_name for _name in vars(_core) if not _name.startswith("_")])

# Tracebacks and help() name them glossy.X, as users write them.
for _name in __all__:
    if isinstance(globals()[_name], type):
        globals()[_name].__module__ = "glossy"
