// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// vtk-bloom command-line tool: errors, argument parsing, error collection from VTK objects and
// the progress bar. Nothing here knows about bloom or files.
#ifndef vtkBloomToolSupport_h
#define vtkBloomToolSupport_h

#include <vtkType.h>

#include <map>
#include <string>
#include <vector>

class vtkAlgorithm;
class vtkObject;

namespace vtkBloomTool
{
/// A usage error: message printed with the usage hint, exit status 2.
struct UsageError
{
  std::string Message;
};

/// A processing error: message printed, exit status 1.
struct RunError
{
  std::string Message;
};

std::string Lower(std::string s);

/// The extension of a path, lower case, with its dot ("" when none).
std::string Extension(const std::string& path);

double ParseDouble(const std::string& option, const std::string& text);
/// A finite number in [lo, hi]; otherwise a UsageError naming the option and the range.
double ParseDoubleIn(const std::string& option, const std::string& text, double lo, double hi);
int ParseInt(const std::string& option, const std::string& text, int lo, int hi);
std::vector<double> ParseList(const std::string& option, const std::string& text);
int ParseChoice(
  const std::string& option, const std::string& text, const std::map<std::string, int>& choices);

/// A count such as 268435456, 300M or 2G (decimal suffixes K, M, G), at least 1.
vtkTypeUInt64 ParseCount(const std::string& option, const std::string& text);

/// Command-line arguments of one command, parsed by CLI11: the flags and the options (with one
/// value each) the command knows, and its positional arguments. A name it does not know, a
/// missing value or an option given twice is a UsageError. The command then takes each option
/// by name and parses its value itself (the Parse* functions above, with their range checks
/// and messages); CheckAllTaken() reports an option it did not use.
class Arguments
{
public:
  Arguments(int argc, char* argv[], int first, const std::vector<std::string>& flags,
    const std::vector<std::string>& options);

  /// Visit a known option; everything not visited is reported as unknown.
  bool Take(const std::string& name, std::string& value);

  void CheckAllTaken() const;

  std::map<std::string, std::string> Options;
  std::vector<std::string> Positional;
};

/// Errors from VTK objects, collected instead of going to the output window.
class ErrorCollector
{
public:
  /// Observe `object`'s ErrorEvent; returns the observer's tag (for RemoveObserver).
  unsigned long Watch(vtkObject* object);

  /// Throw a RunError with `context` and every collected message, if any were collected.
  void ThrowIfAny(const std::string& context);

  std::vector<std::string> Messages;

private:
  static void OnError(vtkObject*, unsigned long, void* clientData, void* callData);
};

/// A progress bar on stderr, shown only when enabled (stderr is a terminal and not --quiet).
/// One bar can span several steps and files: Begin() names the span of the total that the
/// next watched algorithm's 0..1 progress covers.
class ProgressBar
{
public:
  bool Enabled = false;

  void Watch(vtkAlgorithm* algorithm);
  void Begin(const std::string& label, double start, double end);
  void Show(double fraction);
  /// End the bar's line so that a message can be printed; the bar redraws on its next step.
  void Break();
  void Finish();

private:
  static void OnProgress(vtkObject*, unsigned long, void* clientData, void* callData);

  std::string Label;
  double Start = 0.0;
  double End = 1.0;
  int LastPercent = -1;
  std::string LastLabel;
};
}

#endif
