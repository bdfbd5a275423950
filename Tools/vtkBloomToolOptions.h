// The bloom options of `vtk-bloom image` (and render and view): their names, and how they set a
// vtkImageBloom, PSF mode included.
#ifndef vtkBloomToolOptions_h
#define vtkBloomToolOptions_h

#include "vtkBloomToolSupport.h"

#include <string>
#include <vector>

class vtkImageBloom;

namespace vtkBloomTool
{
/// The option names ApplyImageOptions takes (CLI11 refuses any other).
extern const std::vector<std::string> BloomOptionNames;

/**
 * Set `bloom` from the options: --preset first, then every other option over it. Throws
 * UsageError for a bad value, RunError for a PSF file that cannot be read or used.
 */
void ApplyImageOptions(Arguments& args, vtkImageBloom* bloom);
}

#endif
