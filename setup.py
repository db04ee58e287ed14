"""What pyproject.toml cannot say: the checkout's top-level ``derivations/`` folder ships inside the
package as ``symfloat.derivations`` (mapped by ``package_dir``), so that no module named ``derivations``
lands at the top of site-packages; setuptools' package discovery cannot look under a mapped folder, so
the derivation packages are listed here."""
from setuptools import find_packages, setup

setup(packages=[*find_packages(include=["symfloat", "symfloat.*"]), "symfloat.derivations",
                *(f"symfloat.derivations.{name}" for name in find_packages("derivations"))],
      package_dir={"symfloat.derivations": "derivations"})
