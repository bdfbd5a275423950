// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// The bloom options of `vtk-bloom image` (and render and view): their names, parsed and checked
// once into edits of a vtkBloomParameters, PSF mode included.
#ifndef vtkBloomToolOptions_h
#define vtkBloomToolOptions_h

#include "vtkBloomToolSupport.h"

#include <functional>
#include <string>
#include <vector>

class vtkBloomParameters;

namespace vtkBloomTool
{
/// The option names BloomOptions takes (CLI11 refuses any other).
extern const std::vector<std::string> BloomOptionNames;

/**
 * The bloom options given on the command line, parsed once: the constructor takes them from
 * `args` and throws UsageError for a bad value (RunError for a PSF file that cannot be read or
 * used), before anything runs. Apply sets them on parameters, --preset first and every other
 * option over it, as often as needed: `render` applies them after a scene has set its own.
 */
class BloomOptions
{
public:
  explicit BloomOptions(Arguments& args);

  void Apply(vtkBloomParameters* parameters) const;

  /// Whether --psf was given (PSF mode).
  bool GetPSF() const { return this->PSF; }

private:
  void ParsePSF(Arguments& args);

  /// One edit: `setter` with `value`, converted once to the setter's type.
  template <typename T, typename V>
  void Set(void (vtkBloomParameters::*setter)(T), V value)
  {
    const T converted = static_cast<T>(value);
    this->Edits.emplace_back(
      [setter, converted](vtkBloomParameters* p) { (p->*setter)(converted); });
  }

  std::vector<std::function<void(vtkBloomParameters*)>> Edits;
  bool PSF = false;
};
}

#endif
