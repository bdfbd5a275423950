# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
# The vtkbloom Python package: a unittest suite and the script examples, run from the build
# tree. Not in sanitizer builds: a plain python3 cannot load ASan-instrumented extensions.
if (NOT VTKBLOOM_WRAP_PYTHON OR VTKBLOOM_ENABLE_SANITIZERS)
  return ()
endif ()

set(vtkbloom_python_env
  "PYTHONPATH=${VTKBLOOM_PYTHON_BUILD_DIR}:${CMAKE_SOURCE_DIR}/Examples/Python"
  "LD_LIBRARY_PATH=${CMAKE_BINARY_DIR}/${CMAKE_INSTALL_LIBDIR}")
set(vtkbloom_python_out "${CMAKE_CURRENT_BINARY_DIR}/Temporary/Python")
file(MAKE_DIRECTORY "${vtkbloom_python_out}")

add_test(NAME Python.vtkbloom
  COMMAND "${Python3_EXECUTABLE}" "${CMAKE_CURRENT_SOURCE_DIR}/Python/test_vtkbloom.py" -v)

# ParaView's XML states the C++ defaults and enumerations by hand: checked against them.
add_test(NAME Python.ParaViewXML
  COMMAND "${Python3_EXECUTABLE}" "${CMAKE_CURRENT_SOURCE_DIR}/Python/test_paraview_xml.py" -v)
set_tests_properties(Python.ParaViewXML PROPERTIES ENVIRONMENT "${vtkbloom_python_env}"
  SKIP_RETURN_CODE 77 TIMEOUT 60)

add_test(NAME Python.arrays
  COMMAND "${Python3_EXECUTABLE}" "${CMAKE_CURRENT_SOURCE_DIR}/Python/test_arrays.py" -v)
if (VTKBLOOM_ENABLE_RENDERING)
  # add_bloom renders: under the leg's Xvfb, or headless where VTK chooses (9.4 and later).
  add_test(NAME Python.scene
    COMMAND "${Python3_EXECUTABLE}" "${CMAKE_CURRENT_SOURCE_DIR}/Python/test_scene.py" -v)
  set_tests_properties(Python.scene PROPERTIES
    ENVIRONMENT "${vtkbloom_python_env}" SKIP_RETURN_CODE 77 TIMEOUT 120)
  # PyVista's own Plotter: where python3-pyvista is installed (the sid leg requires it), not
  # built where it is not (Debian 12 has no PyVista), rather than run and skipped.
  execute_process(COMMAND "${Python3_EXECUTABLE}" -c "import pyvista"
    RESULT_VARIABLE vtkbloom_no_pyvista OUTPUT_QUIET ERROR_QUIET)
  if (NOT vtkbloom_no_pyvista)
    add_test(NAME Python.pyvista
      COMMAND "${Python3_EXECUTABLE}" "${CMAKE_CURRENT_SOURCE_DIR}/Python/test_pyvista.py" -v)
    set_tests_properties(Python.pyvista PROPERTIES
      ENVIRONMENT "${vtkbloom_python_env}" SKIP_RETURN_CODE 77 TIMEOUT 120)
    # PyVista's plugin points (plotter.bloom, image.bloom, pyvista.read), found through the
    # build tree's dist-info, and the plugin's docstring examples.
    add_test(NAME Python.pyvista.plugin
      COMMAND "${Python3_EXECUTABLE}" "${CMAKE_CURRENT_SOURCE_DIR}/Python/test_pyvista_plugin.py" -v)
    set_tests_properties(Python.pyvista.plugin PROPERTIES
      ENVIRONMENT "${vtkbloom_python_env};VTKBLOOM_SHARED_DATA_DIR=${VTKBLOOM_SHARED_DATA_DIR}"
      SKIP_RETURN_CODE 77 TIMEOUT 300)
  endif ()
  # Long sessions: add_bloom/remove_bloom, emitters and bloom() in loops hold memory flat.
  add_test(NAME Python.soak
    COMMAND "${Python3_EXECUTABLE}" "${CMAKE_CURRENT_SOURCE_DIR}/Python/test_soak.py" -v)
  set_tests_properties(Python.soak PROPERTIES ENVIRONMENT "${vtkbloom_python_env}"
    SKIP_RETURN_CODE 77 TIMEOUT 300)
endif ()

add_test(NAME Python.Example.BatchBloom
  COMMAND "${CMAKE_CURRENT_SOURCE_DIR}/Python/run-with-shared-data.sh"
    "${VTKBLOOM_SHARED_DATA_DIR}/presets"
    "${Python3_EXECUTABLE}" "${CMAKE_SOURCE_DIR}/Examples/Python/batch_bloom.py" --png
    "${VTKBLOOM_SHARED_DATA_DIR}/presets" "${vtkbloom_python_out}/batch")
add_test(NAME Python.Example.SimulationSliceWavelet
  COMMAND "${Python3_EXECUTABLE}" "${CMAKE_SOURCE_DIR}/Examples/Python/bloom_simulation_slice.py"
    "${vtkbloom_python_out}/wavelet-slice")
add_test(NAME Python.Example.SimulationSliceNumpy
  COMMAND "${Python3_EXECUTABLE}" "${CMAKE_SOURCE_DIR}/Examples/Python/bloom_simulation_slice.py"
    --source numpy "${vtkbloom_python_out}/numpy-slice")
add_test(NAME Python.Example.ComparePresets
  COMMAND "${Python3_EXECUTABLE}" "${CMAKE_SOURCE_DIR}/Examples/Python/compare_presets.py"
    "${vtkbloom_python_out}/compare-presets.png")

set_tests_properties(Python.vtkbloom Python.arrays Python.Example.BatchBloom
  Python.Example.SimulationSliceWavelet Python.Example.SimulationSliceNumpy
  Python.Example.ComparePresets
  PROPERTIES ENVIRONMENT "${vtkbloom_python_env}" SKIP_RETURN_CODE 77 TIMEOUT 120)

# docs/python.md's three recipes, each run as written; the pictures in docs/images come from
# them. PyVista's where this Python has it (CI's sid leg), vedo's where it renders.
# Each through check_recipe.py, which compares its frame with the same recipe unbloomed: the
# glow must be there, and bloom only adds light.
set(vtkbloom_check_recipe "${CMAKE_CURRENT_SOURCE_DIR}/Python/check_recipe.py")
add_test(NAME Python.Recipe.Numpy
  COMMAND "${Python3_EXECUTABLE}" "${vtkbloom_check_recipe}" --side-by-side
    "${CMAKE_SOURCE_DIR}/Examples/Python/recipes/numpy_frame.py"
    "${vtkbloom_python_out}/recipe-numpy.png" "${vtkbloom_python_out}/recipe-numpy.exr")
set_tests_properties(Python.Recipe.Numpy PROPERTIES ENVIRONMENT "${vtkbloom_python_env}" TIMEOUT 120)
if (VTKBLOOM_ENABLE_RENDERING)
  foreach (client IN ITEMS pyvista vedo)
    execute_process(COMMAND "${Python3_EXECUTABLE}" -c "import ${client}"
      RESULT_VARIABLE vtkbloom_no_client OUTPUT_QUIET ERROR_QUIET)
    if (vtkbloom_no_client)
      continue ()
    endif ()
    set(recipe "${CMAKE_SOURCE_DIR}/Examples/Python/recipes/vedo_tubes.py")
    if (client STREQUAL "pyvista")
      set(recipe "${CMAKE_SOURCE_DIR}/Examples/Python/recipes/pyvista_lamp.py")
    endif ()
    add_test(NAME Python.Recipe.${client}
      COMMAND "${Python3_EXECUTABLE}" "${vtkbloom_check_recipe}" "${recipe}"
        "${vtkbloom_python_out}/recipe-${client}.png")
    set_tests_properties(Python.Recipe.${client} PROPERTIES
      ENVIRONMENT "${vtkbloom_python_env}" TIMEOUT 120)
    # A sample of the client's own examples through add_bloom at the defaults, as its users
    # run them (Testing/Python/client_examples.py; docs/python.md has the large sweeps): each
    # renders, runs with no error and no GL error its plain frame lacks, and stays within 1 %
    # of its pixels, each viewport on its own. Lines, text, axes, grids, labels, hidden lines,
    # chart marks, and volumes in two renderers (vedo's volume_sharemap).
    if (client STREQUAL "pyvista")
      set(examples
        pyvista.plotting.plotter.BasePlotter.enable_hidden_line_removal
        pyvista.plotting.plotter.BasePlotter.add_point_scalar_labels
        pyvista.plotting.renderer.Renderer.show_grid
        pyvista.plotting.renderer.Renderer.show_bounds
        pyvista.plotting.cube_axes_actor.CubeAxesActor
        pyvista.core.utilities.geometric_objects.Line
        pyvista.core.filters.poly_data.PolyDataFilters.plot_boundaries
        pyvista.core.filters.data_set.DataSetFilters.delaunay_3d
        pyvista.plotting.plotter.BasePlotter.add_points
        pyvista.plotting.charts.Chart2D.plot
        pyvista.plotting.charts.ChartPie
        pyvista.plotting.charts.BarPlot.pen
        pyvista.plotting.charts.Axis.tick_labels)
    else ()
      set(examples
        pyplot/markers.py pyplot/plot_errband.py pyplot/scatter1.py pyplot/quiver.py
        pyplot/intersect2d.py pyplot/histo_1d_a.py pyplot/fit_polynomial1.py
        pyplot/custom_axes2.py basic/legendbox.py basic/colorlines.py basic/delaunay2d.py
        basic/color_mesh_cells1.py volumetric/volume_sharemap.py)
    endif ()
    # An open defect, bounded so that it cannot grow unseen: one pixel of PyVista's
    # hidden-line example (two viewports, wireframes 3 pixels wide; no light) is 6 levels off
    # on VTK 9.6 (docs/python.md, "Not yet").
    set(known)
    if (client STREQUAL "pyvista")
      set(known --known-dark-off
        pyvista.plotting.plotter.BasePlotter.enable_hidden_line_removal=6)
    endif ()
    add_test(NAME Python.ClientExamples.${client}
      COMMAND "${Python3_EXECUTABLE}" "${CMAKE_CURRENT_SOURCE_DIR}/Python/client_examples.py"
        --client ${client} --check --out "${vtkbloom_python_out}/client-examples-${client}"
        ${known} --only ${examples})
    set_tests_properties(Python.ClientExamples.${client} PROPERTIES
      ENVIRONMENT "${vtkbloom_python_env}" TIMEOUT 900)
  endforeach ()
endif ()
