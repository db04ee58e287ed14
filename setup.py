"""What pyproject.toml cannot say: the checkout's top-level ``derivations/`` folder ships inside the
package as ``symfloat.derivations`` (mapped by ``package_dir``), so that no module named ``derivations``
lands at the top of site-packages; setuptools' package discovery cannot look under a mapped folder, so
the derivation packages are listed here; and the one C module, the float64 body clipped by the water plane
(``symfloat/geometry/_clipped.c``: the draught's step and the submerged part), optional: where it cannot be built,
its Python twins serve."""
from setuptools import Extension, find_namespace_packages, find_packages, setup

# -ffp-contract=off: no fused multiply-add, so that the C step rounds as Python's floats do, bit for bit
CLIPPED = Extension("symfloat.geometry._clipped", ["symfloat/geometry/_clipped.c"],
                    extra_compile_args=["-O2", "-ffp-contract=off"], optional=True)

# the package's folders of data (sources, schemas, the site's assets, nbconvert's template) are listed as
# packages too, so that setuptools installs their files without warning that they are in no package
setup(packages=[*find_namespace_packages(include=["symfloat", "symfloat.*"], exclude=["*.__pycache__"]),
                "symfloat.derivations", *(f"symfloat.derivations.{name}" for name in find_packages("derivations"))],
      package_dir={"symfloat.derivations": "derivations"},
      ext_modules=[CLIPPED])
