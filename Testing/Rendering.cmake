# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
# Tests of the render pass (VTKBloom::RenderingBloom); included by Testing/CMakeLists.txt.
# They need an OpenGL context: with the OSMesa VTK they run anywhere; with an X11 VTK they need
# a display (scripts/test.sh runs CTest under xvfb-run there). Every test is named Rendering*.
if (NOT VTKBLOOM_ENABLE_RENDERING)
  return ()
endif ()

set(vtkbloom_rendering_baselines "${CMAKE_CURRENT_LIST_DIR}/Data/Baseline")

vtkbloom_add_gtest(TestBloomPass OPENGL
  SOURCES Rendering/TestBloomPass.cxx Rendering/TestBloomPassLiveScenes.cxx
    Rendering/TestBloomPassSelective.cxx Rendering/TestBloomPassPSF.cxx
    Rendering/TestBloomPassFFTBlur.cxx
  LIBRARIES vtkbloom_scenes VTKBloom::RenderingBloom VTKBloom::FiltersBloom VTKBloom::IOOpenEXR
    VTK::TestingRendering VTK::IOImage
    VTK::RenderingOpenGL2 VTK::RenderingCore VTK::FiltersSources VTK::CommonDataModel
    VTK::CommonCore)
vtk_module_autoinit(TARGETS TestBloomPass MODULES VTK::RenderingOpenGL2)
target_compile_definitions(TestBloomPass PRIVATE
  VTKBLOOM_BASELINE_DIR="${vtkbloom_rendering_baselines}")

# The numerical hard cases of issue 4 on the GPU (the CPU suite is NumericsHardCases).
vtkbloom_add_gtest(TestBloomPassHardCases OPENGL
  SOURCES Rendering/TestBloomPassHardCases.cxx
  LIBRARIES vtkbloom_hardcases VTKBloom::RenderingBloom VTKBloom::FiltersBloom
    VTKBloom::IOOpenEXR VTK::RenderingOpenGL2 VTK::RenderingCore VTK::CommonDataModel
    VTK::CommonCore)
vtk_module_autoinit(TARGETS TestBloomPassHardCases MODULES VTK::RenderingOpenGL2)

# The content-aware chain against the full chain, bit for bit, and the fast mode.
vtkbloom_add_gtest(TestBloomPassRegion OPENGL
  FILTER -RenderingBloomPassCompute.OlderContextWithTheExtensions
  SOURCES Rendering/TestBloomPassRegion.cxx
  LIBRARIES vtkbloom_scenes VTKBloom::RenderingBloom VTKBloom::FiltersBloom
    VTK::RenderingOpenGL2 VTK::RenderingCore VTK::CommonDataModel VTK::CommonCore)
vtk_module_autoinit(TARGETS TestBloomPassRegion MODULES VTK::RenderingOpenGL2)
# The compute passes in an older context that lists their extensions (NVIDIA's 3.2 under VTK
# 9.6's EGL window): Mesa reports OpenGL 3.3 here.
if (VTKBLOOM_ENABLE_RENDERING)
  add_test(NAME RenderingBloomPassCompute.InAnOpenGL33Context
    COMMAND TestBloomPassRegion
      --gtest_filter=RenderingBloomPassCompute.OlderContextWithTheExtensions)
  set(environment "MESA_GL_VERSION_OVERRIDE=3.3" "VTKBLOOM_EXPECT_OLDER_CONTEXT=1")
  if (VTKBLOOM_ENABLE_SANITIZERS)
    # As vtkbloom_add_gtest's OpenGL tests: Mesa's own allocations are no leaks of ours.
    list(APPEND environment "ASAN_OPTIONS=detect_leaks=0:abort_on_error=1:quarantine_size_mb=32")
  endif ()
  set_tests_properties(RenderingBloomPassCompute.InAnOpenGL33Context PROPERTIES
    ENVIRONMENT "${environment}")
endif ()

# Light, not the frame (issue 35): the defaults, the background, the annotations, emitters.
# Text needs VTK's FreeType module (every VTK the scripts build or install has it).
if (TARGET VTK::RenderingFreeType)
  vtkbloom_add_gtest(TestBloomPassLight OPENGL
    SOURCES Rendering/TestBloomPassLight.cxx
    LIBRARIES VTKBloom::RenderingBloom VTKBloom::FiltersBloom VTK::RenderingFreeType
      VTK::RenderingOpenGL2 VTK::RenderingCore VTK::FiltersSources VTK::CommonDataModel
      VTK::CommonCore)
  vtk_module_autoinit(TARGETS TestBloomPassLight
    MODULES VTK::RenderingOpenGL2 VTK::RenderingFreeType)
endif ()

# Tiled frames (vtkWindowToImageFilter with a scale) bloom as one frame (issue 36, part 2).
vtkbloom_add_gtest(TestBloomPassTiles OPENGL
  SOURCES Rendering/TestBloomPassTiles.cxx
  LIBRARIES VTKBloom::RenderingBloom VTK::RenderingOpenGL2 VTK::RenderingCore
    VTK::FiltersSources VTK::CommonDataModel VTK::CommonCore)
vtk_module_autoinit(TARGETS TestBloomPassTiles MODULES VTK::RenderingOpenGL2)

# What the bloom frame costs over the plain frame, counted (shader invocations, full-size passes,
# bytes), not timed: a full-frame draw or copy added around the chain fails here.
vtkbloom_add_gtest(TestBloomPassFrameCost OPENGL
  SOURCES Rendering/TestBloomPassFrameCost.cxx
  LIBRARIES vtkbloom_scenes VTKBloom::RenderingBloom VTK::RenderingOpenGL2 VTK::RenderingCore
    VTK::CommonDataModel VTK::CommonCore)
vtk_module_autoinit(TARGETS TestBloomPassFrameCost MODULES VTK::RenderingOpenGL2)

# Long sessions: the bloom, its emitters, presets, PSF mode, tiles, several windows and the
# context switched for hundreds of frames hold their memory flat against the plain renderer.
vtkbloom_add_gtest(TestBloomPassSoak OPENGL
  SOURCES Rendering/TestBloomPassSoak.cxx
  LIBRARIES VTKBloom::RenderingBloom VTKBloom::FiltersBloom VTK::RenderingOpenGL2
    VTK::RenderingCore VTK::FiltersCore VTK::FiltersSources VTK::CommonDataModel VTK::CommonCore)
vtk_module_autoinit(TARGETS TestBloomPassSoak MODULES VTK::RenderingOpenGL2)

# Temporal stability: the bloom's energy under sub-pixel camera motion against the scene's.
vtkbloom_add_gtest(TestBloomPassMotion OPENGL
  SOURCES Rendering/TestBloomPassMotion.cxx
  LIBRARIES vtkbloom_scenes VTKBloom::RenderingBloom VTKBloom::FiltersBloom
    VTK::RenderingOpenGL2 VTK::RenderingCore VTK::CommonDataModel VTK::CommonCore)
vtk_module_autoinit(TARGETS TestBloomPassMotion MODULES VTK::RenderingOpenGL2)

# The gallery: the pass at its defaults on the scenes users build (backgrounds, annotations,
# viewports, layers, widgets, depth peeling, volumes, FXAA, tone mapping, SSAO, picking, ...),
# each against the same frame without the pass, and one emitter's glow (docs' gallery).
if (TARGET VTK::InteractionWidgets AND TARGET VTK::RenderingFreeType AND
    TARGET VTK::RenderingAnnotation)
  vtkbloom_add_gtest(TestBloomPassGallery OPENGL
    SOURCES Rendering/TestBloomPassGallery.cxx Support/vtkBloomGallery.cxx
    LIBRARIES VTKBloom::RenderingBloom VTKBloom::FiltersBloom VTK::InteractionWidgets
      VTK::InteractionStyle VTK::RenderingAnnotation VTK::RenderingFreeType
      VTK::RenderingVolumeOpenGL2 VTK::RenderingVolume VTK::ImagingCore VTK::IOImage
      VTK::FiltersCore VTK::FiltersSources VTK::RenderingOpenGL2 VTK::RenderingCore
      VTK::CommonDataModel VTK::CommonCore)
  set(vtkbloom_gallery_autoinit VTK::RenderingOpenGL2 VTK::RenderingVolumeOpenGL2
    VTK::RenderingFreeType VTK::InteractionStyle)
  # A chart's marks (vtkChartXY in a vtkContextActor), where this VTK has the chart modules
  # (the OSMesa and EGL builds of scripts/lib/build-debian-vtk.sh do not).
  if (TARGET VTK::ChartsCore AND TARGET VTK::RenderingContext2D AND
      TARGET VTK::RenderingContextOpenGL2)
    target_link_libraries(TestBloomPassGallery PRIVATE VTK::ChartsCore VTK::RenderingContext2D
      VTK::RenderingContextOpenGL2)
    target_compile_definitions(TestBloomPassGallery PRIVATE VTKBLOOM_GALLERY_CHARTS=1)
    list(APPEND vtkbloom_gallery_autoinit VTK::RenderingContextOpenGL2)
  endif ()
  # Point labels (vtkLabeledDataMapper), where this VTK has the labelling module (Debian's and
  # sid's; not the cached OSMesa and EGL prefixes).
  if (TARGET VTK::RenderingLabel)
    target_link_libraries(TestBloomPassGallery PRIVATE VTK::RenderingLabel)
    target_compile_definitions(TestBloomPassGallery PRIVATE VTKBLOOM_GALLERY_LABELS=1)
  endif ()
  vtk_module_autoinit(TARGETS TestBloomPassGallery MODULES ${vtkbloom_gallery_autoinit})
endif ()
