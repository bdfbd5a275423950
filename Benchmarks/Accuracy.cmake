# The accuracy-versus-time study (issue 4): a plain harness, run by scripts/accuracy-study.sh.
# vtkImageGaussianSmooth (VTK::ImagingGeneral) is its comparison row.
find_package(VTK 9.1 QUIET COMPONENTS ImagingGeneral)
add_executable(BloomAccuracyStudy "${CMAKE_CURRENT_LIST_DIR}/BloomAccuracyStudy.cxx")
target_link_libraries(BloomAccuracyStudy PRIVATE VTKBloom::FiltersBloom VTK::ImagingGeneral
  VTK::ImagingCore VTK::CommonExecutionModel VTK::CommonDataModel VTK::CommonCore
  vtkbloom_build_flags)
