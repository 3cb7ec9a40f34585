"""Installation script of sage_dynsym (also usable as ``sage -pip install .``)."""
import glob

from setuptools import setup, find_packages

setup(
    name="sage_dynsym",
    version="0.1.0",
    description=("Symbolic modelling and qualitative analysis of dynamic "
                 "systems (rigid bodies, electrical circuits) in SageMath"),
    long_description=open("README.md", encoding="utf-8").read(),
    long_description_content_type="text/markdown",
    author="The sage_dynsym developers",
    author_email="maintainers@users.noreply.h-seed-5afc3da0.example",
    # an SPDX expression (Metadata 2.4: License-Expression; no license classifier)
    license="GPL-2.0-or-later",
    # the full text, in the source distribution and in the wheel
    license_files=["LICENSE"],
    keywords=("SageMath analytical-mechanics Lagrangian Hamiltonian Routh "
              "stability Lyapunov circuits Brayton-Moser Lie-Poisson"),
    classifiers=[
        "Development Status :: 3 - Alpha",
        "Intended Audience :: Science/Research",
        "Intended Audience :: Education",
        "Operating System :: POSIX :: Linux",
        "Operating System :: MacOS",
        "Programming Language :: Python :: 3",
        "Programming Language :: Python :: 3 :: Only",
        "Programming Language :: Python :: 3.10",
        "Programming Language :: Python :: 3.11",
        "Programming Language :: Python :: 3.12",
        "Topic :: Scientific/Engineering :: Mathematics",
        "Topic :: Scientific/Engineering :: Physics",
        "Topic :: Scientific/Engineering :: Electronic Design Automation (EDA)",
        "Framework :: Jupyter",
    ],
    python_requires=">=3.10",
    packages=find_packages(include=["sage_dynsym", "sage_dynsym.*"]),
    # Sage itself is not listed: inside an existing SageMath it is already
    # there, and the project .venv installs passagemath-standard (Makefile).
    install_requires=["pyyaml"],
    extras_require={
        "passagemath": ["passagemath-standard~=10.8", "passagemath-qepcad~=10.8"],
        "test": ["pytest", "sympy", "scipy"],
        # sage_dynsym.scale (stability maps and sweeps on Dask)
        "scale": ["dask[distributed]>=2024.1,<2027", "scipy"],
    },
    # the bundled description files, also for a non-editable install
    data_files=[("share/sage_dynsym/examples", sorted(glob.glob("examples/*.yaml")))],
    entry_points={"console_scripts": ["sage-dynsym = sage_dynsym.__main__:main"]},
)
