// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// vtk-bloom command-line tool: which output each input goes to (one file, or a batch into a
// directory), what happened to each file, and the --stats JSON report.
#ifndef vtkBloomToolBatch_h
#define vtkBloomToolBatch_h

#include <vtkType.h>

#include <string>
#include <vector>

namespace vtkBloomTool
{
/// One input and its output. A non-empty Problem means it must not run (the reason why).
struct FileJob
{
  std::string Input;
  std::string Output;
  std::string Problem;
};

/// IN and OUT of the single-file form: OUT must be .exr or .png, IN must exist, and OUT must
/// not be IN or a directory. Throws UsageError or RunError.
FileJob PlanSingle(const std::string& input, const std::string& output);

/// The batch form: OUTDIR/NAME.exr (or .png, by `extension`) for each input IN/NAME.ext,
/// creating OUTDIR when missing. An input that does not exist, an output that already exists
/// (nothing is overwritten) and a second input with the same NAME get a Problem; the others
/// run. Throws RunError when OUTDIR cannot be made.
std::vector<FileJob> PlanBatch(const std::vector<std::string>& inputs, const std::string& directory,
  const std::string& extension);

/// What happened to one file, for the --stats report.
struct FileReport
{
  std::string Input;
  std::string Output;
  bool Succeeded = false;
  std::string Error;
  double Seconds = 0.0;
  int Width = 0;
  int Height = 0;
  // vtkImageBloom's statistics of the update (image command only).
  bool HasBloomStatistics = false;
  bool Exact = false;
  bool BloomSkipped = false;
  double EnergyIn = 0.0;
  double EnergyOut = 0.0;
  vtkIdType NumberOfBrightPixels = 0;
  double PeakLuminanceIn = 0.0;
  double PeakLuminanceOut = 0.0;
  int NumberOfLevelsUsed = 0;
};

/// Write the reports as a JSON document {"command": ..., "files": [...]} to `path`, through a
/// temporary file. Non-finite numbers are written as null. Throws RunError.
void WriteStatistics(
  const std::string& path, const std::string& command, const std::vector<FileReport>& reports);
}

#endif
