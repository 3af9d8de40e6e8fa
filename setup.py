"""The build pip runs (pyproject.toml): CMake builds the library and the
module (python/), and both are put in the package, the library beside the
module, which finds it there ($ORIGIN). DEEPGUIDE_BUILD_DIR reuses a CMake
build tree (scripts/test.sh's build/, say) instead of making build-python/."""

import os
import pathlib
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = pathlib.Path(__file__).resolve().parent


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        build = pathlib.Path(os.environ.get("DEEPGUIDE_BUILD_DIR") or ROOT / "build-python").resolve()
        if not (build / "CMakeCache.txt").exists():
            subprocess.check_call(["cmake", "-S", str(ROOT), "-B", str(build), "-G", "Ninja",
                                   "-DCMAKE_BUILD_TYPE=Release", "-DDEEPGUIDE_BUILD_TESTS=OFF",
                                   "-DDEEPGUIDE_PYTHON=ON", f"-DPython3_EXECUTABLE={sys.executable}"])
        subprocess.check_call(["cmake", "--build", str(build), "--target", "deepguide_python",
                               "-j", str(os.cpu_count() or 2)])
        target = pathlib.Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        built = sorted((build / "python" / "deepguide").glob("_deepguide*.so"))
        if not built:
            sys.exit(f"deepguide: CMake built no module in {build / 'python' / 'deepguide'}")
        shutil.copy2(built[0], target)
        shutil.copy2((build / "lib" / "libdeepguide.so.0").resolve(), target.parent / "libdeepguide.so.0")


setup(
    packages=["deepguide"],
    package_dir={"": "python"},
    ext_modules=[Extension("deepguide._deepguide", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    # setuptools' own build/ would land in CMake's build tree.
    options={"build": {"build_base": "build-setuptools"}, "egg_info": {"egg_base": "build-setuptools"}},
    zip_safe=False,
)
