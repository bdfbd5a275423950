#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
# Run by scripts/test-deb.sh inside a clean Debian root: install vtk-bloom's packages from
# DEBDIR with apt and check that each works as installed, with no PYTHONPATH and no
# LD_LIBRARY_PATH.
#
#   bash scripts/lib/deb-test-in-root.sh DEBDIR SUITE
#
# SUITE (bookworm or sid) says what the release must have: sid packages PyVista 0.49, whose
# plugin points must then find plotter.bloom and pyvista.read('x.exr'); Debian 12 has no
# PyVista, and there the entry points must do no harm.
set -euo pipefail
debs=$1 suite=$2
export DEBIAN_FRONTEND=noninteractive
unset PYTHONPATH LD_LIBRARY_PATH
work=$(mktemp -d)
cd "$work"
apt_install() { apt-get install -y -q --no-install-recommends "$@" >"$work/apt.log" ||
  { tail -n 30 "$work/apt.log" >&2; exit 1; }; }
check() { echo "deb-test: $*"; }

apt-get update -q >/dev/null
check "apt install ./*.deb ($(cd "$debs" && echo *.deb))"
apt_install "$debs"/*.deb
dpkg-query -W -f='  ${Package} ${Version}\n' libvtkbloom\* vtk-bloom python3-vtkbloom paraview-vtkbloom

check "vtk-bloom --version"
vtk-bloom --version | grep -q "^vtk-bloom [0-9]"
check "vtk-bloom --help"
vtk-bloom --help >help.txt
head -n 2 help.txt
[ "$(command -v vtk-bloom)" = /usr/bin/vtk-bloom ]

check "python3: import vtkbloom, and a numpy round trip through vtkbloom.bloom"
python3 -c "import vtkbloom; print(vtkbloom.bloom)"
python3 - <<'EOF'
import numpy as np
import vtkbloom

print("vtkbloom", vtkbloom.__version__, "from", vtkbloom.__file__)
assert vtkbloom.__file__.startswith("/usr/lib/python3/dist-packages/vtkbloom/")
frame = np.zeros((48, 64, 3), np.float32)
frame[24, 32] = 50.0  # one HDR light
glow = vtkbloom.bloom(frame, preset="webgpu-market")
assert glow.shape == frame.shape and glow.dtype == frame.dtype, (glow.shape, glow.dtype)
assert glow[24, 28].min() > 0 and glow[0, 0].max() < glow[24, 28].min(), "no bloom around the light"
print("bloom: light spread to its neighbours,", glow[24, 28])
vtkbloom.write_exr("in.exr", frame, pixel_type="float")
EOF

check "python3: the distribution's metadata and PyVista's entry points, harmless without PyVista"
python3 - <<'EOF'
import sys
from importlib.metadata import entry_points, version

import vtkbloom

assert version("vtkbloom") == vtkbloom.__version__, (version("vtkbloom"), vtkbloom.__version__)
found = {(e.group, e.name, e.value) for g in ("pyvista.plotter_components", "pyvista.accessors",
                                               "pyvista.readers") for e in entry_points(group=g)}
assert ("pyvista.readers", "exr", "vtkbloom.pyvista_plugin:read") in found, found
assert "vtkbloom.pyvista_plugin" not in sys.modules  # only PyVista imports it
print("entry points:", sorted(found))
EOF
if [ "$suite" = sid ]; then
  check "PyVista finds plotter.bloom and pyvista.read('x.exr') with no import of vtkbloom"
  apt_install python3-pyvista
  python3 -c "import numpy as np, vtkbloom; vtkbloom.write_exr('x.exr', np.full((4, 6, 3), 2.0, np.float32))"
  python3 - <<'EOF'
import sys

import pyvista as pv

assert "vtkbloom" not in sys.modules, "imported with pyvista"
# PyVista's own listings, before anything of vtkbloom's is used.
print("registered_plotter_components:",
      [(r.name, r.component.__module__) for r in pv.registered_plotter_components() if r.name == "bloom"])
print("registered_accessors:",
      [(r.name, r.target.__name__) for r in pv.registered_accessors() if r.name == "bloom"])
print("registered_readers:",
      [(r.extension, r.handler.__module__) for r in pv.registered_readers() if r.extension == ".exr"])
pl = pv.Plotter(off_screen=True)
pl.bloom.enable()
assert [p.GetClassName() for p in pl.bloom.passes] == ["vtkBloomPass"], pl.bloom.passes
image = pv.read("x.exr")
assert isinstance(image, pv.ImageData) and image.dimensions == (6, 4, 1), image
assert float(image.bloom.apply().point_data[image.array_names[0]].max()) >= 2.0
pl.close()
print("plotter.bloom.enable(), pv.read('x.exr') and image.bloom.apply() with no import of vtkbloom")
EOF
else
  check "PyVista: not packaged in Debian $(cat /etc/debian_version); the sid leg runs its check"
fi

check "vtk-bloom image in.exr out.exr"
vtk-bloom image --preset webgpu-market in.exr out.exr
python3 -c "
import numpy as np, vtkbloom
image = vtkbloom.read_exr('out.exr')
assert image.shape[:2] == (48, 64) and image[24, 28, 0] > 0, image.shape
print('vtk-bloom image: bloomed', image.shape)"

check "a find_package(VTKBloom) consumer, built with CMake and run"
apt_install cmake g++ make
mkdir consumer
cat >consumer/CMakeLists.txt <<'EOF'
cmake_minimum_required(VERSION 3.16)
project(Consumer CXX)
find_package(VTKBloom REQUIRED)
add_executable(consumer consumer.cxx)
target_link_libraries(consumer PRIVATE VTKBloom::FiltersBloom VTK::CommonDataModel)
EOF
cat >consumer/consumer.cxx <<'EOF'
#include <vtkImageBloom.h>
#include <vtkImageData.h>
#include <vtkNew.h>

#include <algorithm>
#include <iostream>

int main()
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(64, 48, 1);
  image->AllocateScalars(VTK_FLOAT, 3);
  float* pixels = static_cast<float*>(image->GetScalarPointer());
  std::fill(pixels, pixels + 64 * 48 * 3, 0.0f);
  std::fill_n(static_cast<float*>(image->GetScalarPointer(32, 24, 0)), 3, 50.0f);
  vtkNew<vtkImageBloom> bloom;
  bloom->SetPreset("webgpu-market");
  bloom->SetInputData(image);
  bloom->Update();
  const float* near = static_cast<float*>(bloom->GetOutput()->GetScalarPointer(28, 24, 0));
  std::cout << "consumer: vtkImageBloom put " << near[0] << " beside the light" << std::endl;
  return near[0] > 0.0f ? 0 : 1;
}
EOF
cmake -S consumer -B consumer/build -DCMAKE_BUILD_TYPE=Release >consumer.log ||
  { cat consumer.log >&2; exit 1; }
cmake --build consumer/build >>consumer.log || { cat consumer.log >&2; exit 1; }
grep -m1 'VTKBloom_DIR:PATH' consumer/build/CMakeCache.txt
consumer/build/consumer

# pvbatch needs ParaView's Python (python3-paraview). In Debian 12 it conflicts with
# python3-vtk9, which apt then removes, with python3-vtkbloom: the checks above are done.
check "ParaView: pvbatch loads the plugin by its name"
apt_install python3-paraview
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export PRTE_ALLOW_RUN_AS_ROOT=1 PRTE_ALLOW_RUN_AS_ROOT_CONFIRM=1
cat >plugin.py <<'EOF'
from paraview.simple import *
from paraview import servermanager

# Located by name in ParaView's plugin directory, as `paraview --plugins=VTKBloom` does.
servermanager.vtkSMProxyManager.GetProxyManager().GetPluginManager() \
    .LoadPluginConfigurationXMLFromString('<Plugins><Plugin name="VTKBloom"/></Plugins>',
                                          servermanager.ActiveConnection.Session, False)
info = servermanager.vtkSMProxyManager.GetProxyManager().GetPluginManager().GetLocalInformation()
found = [info.GetPluginFileName(i) for i in range(info.GetNumberOfPlugins())
         if info.GetPluginName(i) == "VTKBloom"]
print("available plugin VTKBloom:", found)
LoadDistributedPlugin("VTKBloom", remote=False, ns=globals())
wavelet = Wavelet(WholeExtent=[0, 63, 0, 47, 0, 0])
hdr = Calculator(Input=wavelet, ResultArrayName="rgb", ResultArrayType="Float",
                 Function="(RTData/120)^6*iHat + 0.5*jHat + 0.1*kHat")
bloom = Bloom(Input=hdr, Preset="webgpu-market")
bloom.Scalars = ["POINTS", "rgb"]
bloom.UpdatePipeline()
points = bloom.GetDataInformation().GetNumberOfPoints()
assert points == 64 * 48, points
print("pvbatch: plugin VTKBloom loaded, Bloom filter ran on", points, "points")
EOF
pvbatch plugin.py 2>&1 | grep -v '^$' | tee pvbatch.log
grep -q 'Bloom filter ran' pvbatch.log

check "lintian"
apt_install lintian
lintian --version
lintian --display-level ">=info" --fail-on error "$debs"/*.deb || {
  echo "deb-test: lintian reports errors" >&2
  exit 1
}
echo "deb-test: all checks passed"
