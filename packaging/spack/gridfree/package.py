# SPDX-License-Identifier: GPL-3.0-or-later
# Spack recipe of gridfree (CMakePackage), in the layout of Spack's builtin
# package repository (Spack 1.x: build systems imported from
# spack_repo.builtin). Untested here: Spack cannot run on the machines this
# project is built on (docs/INSTALL.md "Spack"). Use it from a local repo:
#   spack repo create myrepo && cp -r packaging/spack/gridfree myrepo/packages/
#   spack install gridfree
# Versions come from the git tag (v0.2.0); with a release archive instead,
# `spack checksum gridfree 0.2.0` gives its sha256.

from spack_repo.builtin.build_systems.cmake import CMakePackage

from spack.package import *


class Gridfree(CMakePackage):
    """Grid-free extrapolation and numerical uncertainty of CFD-DEM results:
    steady gas flow through a frozen particle bed on many grids, Gaussian
    filtering, and least-squares Richardson extrapolation of the pressure
    drop to the grid-free limit (Fullmer & Musser 2018)."""

    # Where the repository is published: set both before use (the project
    # names no public address yet).
    homepage = "https://example.org/gridfree"
    git = "https://example.org/gridfree.git"

    license("GPL-3.0-or-later")

    version("main", branch="main")
    version("0.2.0", tag="v0.2.0")

    variant("tests", default=False, description="Build the test suite (needs GoogleTest)")

    depends_on("cxx", type="build")
    depends_on("cmake@3.25:", type="build")
    depends_on("pkgconfig", type="build")

    depends_on("eigen@3.4:")
    depends_on("nlohmann-json@3.10:")
    depends_on("sqlite@3:")
    depends_on("spdlog")
    depends_on("fmt")
    depends_on("cli11@2:")
    depends_on("fftw@3 precision=double")
    # Found at configure time when the tests are built, so a build dependency.
    depends_on("googletest", type="build", when="+tests")

    # C++20 and OpenMP; built and tested with GCC 12.
    conflicts("%gcc@:10", msg="gridfree is C++20 (built and tested with GCC 12)")

    def cmake_args(self):
        return [
            self.define_from_variant("GRIDFREE_BUILD_TESTS", "tests"),
            self.define("GRIDFREE_BUILD_BENCH", False),
            self.define("GRIDFREE_FETCH_DEPS", False),
        ]

    @run_after("install")
    @on_package_attributes(run_tests=True)
    def check_install(self):
        gridfree = Executable(self.prefix.bin.gridfree)
        gridfree("--version")

    def setup_run_environment(self, env):
        env.set("GRIDFREE_ROOT", self.prefix)
