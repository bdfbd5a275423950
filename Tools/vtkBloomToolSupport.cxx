// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkBloomToolSupport.h"

#include <vtkAlgorithm.h>
#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkNew.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <sstream>

namespace vtkBloomTool
{
//------------------------------------------------------------------------------
std::string Lower(std::string s)
{
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

//------------------------------------------------------------------------------
std::string Extension(const std::string& path)
{
  return Lower(std::filesystem::path(path).extension().string());
}

//------------------------------------------------------------------------------
double ParseDouble(const std::string& option, const std::string& text)
{
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || errno == ERANGE || !std::isfinite(value))
  {
    throw UsageError{ option + " expects a finite number, got '" + text + "'" };
  }
  return value;
}

//------------------------------------------------------------------------------
double ParseDoubleIn(const std::string& option, const std::string& text, double lo, double hi)
{
  const double value = ParseDouble(option, text);
  if (value < lo || value > hi)
  {
    std::ostringstream range;
    range << option << " must be in [" << lo << ", " << hi << "], got " << text;
    throw UsageError{ range.str() };
  }
  return value;
}

//------------------------------------------------------------------------------
int ParseInt(const std::string& option, const std::string& text, int lo, int hi)
{
  char* end = nullptr;
  errno = 0;
  const long value = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || errno == ERANGE || value < lo || value > hi)
  {
    throw UsageError{ option + " expects an integer in [" + std::to_string(lo) + ", " +
      std::to_string(hi) + "], got '" + text + "'" };
  }
  return static_cast<int>(value);
}

//------------------------------------------------------------------------------
std::vector<double> ParseList(const std::string& option, const std::string& text)
{
  std::vector<double> values;
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ','))
  {
    values.push_back(ParseDouble(option, item));
  }
  if (values.empty())
  {
    throw UsageError{ option + " expects a comma-separated list of numbers" };
  }
  return values;
}

//------------------------------------------------------------------------------
int ParseChoice(
  const std::string& option, const std::string& text, const std::map<std::string, int>& choices)
{
  const auto it = choices.find(Lower(text));
  if (it == choices.end())
  {
    std::string valid;
    for (const auto& choice : choices)
    {
      valid += (valid.empty() ? "" : " | ") + choice.first;
    }
    throw UsageError{ option + " expects one of " + valid + ", got '" + text + "'" };
  }
  return it->second;
}

//------------------------------------------------------------------------------
vtkTypeUInt64 ParseCount(const std::string& option, const std::string& text)
{
  std::string digits = text;
  vtkTypeUInt64 scale = 1;
  if (!digits.empty() && std::isalpha(static_cast<unsigned char>(digits.back())))
  {
    const char suffix = static_cast<char>(std::toupper(static_cast<unsigned char>(digits.back())));
    scale = suffix == 'K' ? 1000ull
      : suffix == 'M'     ? 1000000ull
      : suffix == 'G'     ? 1000000000ull
                          : 0;
    digits.pop_back();
  }
  char* end = nullptr;
  errno = 0;
  const unsigned long long value = std::strtoull(digits.c_str(), &end, 10);
  if (scale == 0 || digits.empty() || digits[0] == '-' || *end != '\0' || errno == ERANGE ||
    value == 0 || value > std::numeric_limits<vtkTypeUInt64>::max() / scale)
  {
    throw UsageError{ option + " expects a positive count such as 300000000, 300M or 2G, got '" +
      text + "'" };
  }
  return static_cast<vtkTypeUInt64>(value) * scale;
}

//------------------------------------------------------------------------------
Arguments::Arguments(int argc, char* argv[], int first, const std::vector<std::string>& flags,
  const std::vector<std::string>& options)
{
  CLI::App app;
  app.set_help_flag(); // --help is handled before any command runs
  app.allow_extras(false);
  app.positionals_at_end(false);
  std::map<std::string, std::string> values;
  std::map<std::string, bool> given;
  for (const std::string& flag : flags)
  {
    app.add_flag(flag, given[flag]);
  }
  for (const std::string& option : options)
  {
    app.add_option(option, values[option])->type_name("VALUE");
  }
  app.add_option("arguments", this->Positional);
  try
  {
    // CLI11 skips its argv[0]; the command's own arguments start at `first`.
    app.parse(argc - first + 1, argv + first - 1);
  }
  catch (const CLI::ParseError& e)
  {
    // Today's wording for the common cases; CLI11's own for the rest.
    std::string message = e.what();
    const std::string name = message.substr(0, message.find(':'));
    if (message.find("not expected") != std::string::npos)
    {
      message = "unknown option" + message.substr(message.find(':'));
    }
    else if (message.find("VALUE missing") != std::string::npos)
    {
      message = name + " needs a value";
    }
    else if (message.find("At Most 1") != std::string::npos)
    {
      message = name + " is given more than once";
    }
    throw UsageError{ message };
  }
  for (const auto& flag : given)
  {
    if (flag.second)
    {
      this->Options[flag.first] = "";
    }
  }
  for (const std::string& option : options)
  {
    if (app.count(option) > 0)
    {
      this->Options[option] = values[option];
    }
  }
}

//------------------------------------------------------------------------------
bool Arguments::Take(const std::string& name, std::string& value)
{
  const auto it = this->Options.find(name);
  if (it == this->Options.end())
  {
    return false;
  }
  value = it->second;
  this->Options.erase(it);
  return true;
}

//------------------------------------------------------------------------------
void Arguments::CheckAllTaken() const
{
  if (!this->Options.empty())
  {
    throw UsageError{ "unknown option " + this->Options.begin()->first };
  }
}

//------------------------------------------------------------------------------
void ErrorCollector::OnError(vtkObject*, unsigned long, void* clientData, void* callData)
{
  auto* self = static_cast<ErrorCollector*>(clientData);
  std::string text = callData ? static_cast<const char*>(callData) : "unknown error";
  // Keep the message and drop VTK's "ERROR: In file, line N / Class (0x...): " prefix.
  const auto pos = text.find("): ");
  if (pos != std::string::npos)
  {
    text = text.substr(pos + 3);
  }
  // One line of printable text: VTK appends the request's dump to pipeline failures, and a
  // reader quotes what it found, which in a garbage file is binary.
  text = text.substr(0, text.find('\n'));
  for (char& c : text)
  {
    c = std::isprint(static_cast<unsigned char>(c)) ? c : '?';
  }
  if (text.size() > 160)
  {
    text = text.substr(0, 157) + "...";
  }
  while (!text.empty() && text.back() == ' ')
  {
    text.pop_back();
  }
  self->Messages.push_back(text);
}

//------------------------------------------------------------------------------
unsigned long ErrorCollector::Watch(vtkObject* object)
{
  vtkNew<vtkCallbackCommand> command;
  command->SetCallback(&ErrorCollector::OnError);
  command->SetClientData(this);
  return object->AddObserver(vtkCommand::ErrorEvent, command);
}

//------------------------------------------------------------------------------
void ErrorCollector::ThrowIfAny(const std::string& context)
{
  if (!this->Messages.empty())
  {
    std::string all = context;
    for (const auto& m : this->Messages)
    {
      all += "\n  " + m;
    }
    this->Messages.clear();
    throw RunError{ all };
  }
}

//------------------------------------------------------------------------------
void ProgressBar::OnProgress(vtkObject*, unsigned long, void* clientData, void* callData)
{
  auto* self = static_cast<ProgressBar*>(clientData);
  const double fraction = callData ? *static_cast<double*>(callData) : 0.0;
  self->Show(self->Start + (self->End - self->Start) * fraction);
}

//------------------------------------------------------------------------------
void ProgressBar::Watch(vtkAlgorithm* algorithm)
{
  if (!this->Enabled)
  {
    return;
  }
  vtkNew<vtkCallbackCommand> command;
  command->SetCallback(&ProgressBar::OnProgress);
  command->SetClientData(this);
  algorithm->AddObserver(vtkCommand::ProgressEvent, command);
}

//------------------------------------------------------------------------------
void ProgressBar::Begin(const std::string& label, double start, double end)
{
  this->Label = label;
  this->Start = start;
  this->End = end;
  this->Show(start);
}

//------------------------------------------------------------------------------
void ProgressBar::Show(double fraction)
{
  if (!this->Enabled)
  {
    return;
  }
  const int percent = static_cast<int>(std::floor(100.0 * std::min(std::max(fraction, 0.0), 1.0)));
  if (percent == this->LastPercent && this->Label == this->LastLabel)
  {
    return;
  }
  this->LastPercent = percent;
  this->LastLabel = this->Label;
  const int filled = percent * 30 / 100;
  std::fprintf(stderr, "\r%-14.14s [%s%s] %3d%%", this->Label.c_str(),
    std::string(filled, '#').c_str(), std::string(30 - filled, ' ').c_str(), percent);
  std::fflush(stderr);
}

//------------------------------------------------------------------------------
void ProgressBar::Break()
{
  if (this->Enabled && this->LastPercent >= 0)
  {
    std::fprintf(stderr, "\n");
    this->LastPercent = -1;
  }
}

//------------------------------------------------------------------------------
void ProgressBar::Finish()
{
  if (this->Enabled && this->LastPercent >= 0)
  {
    this->Show(1.0);
    std::fprintf(stderr, "\n");
    std::fflush(stderr);
    this->LastPercent = -1;
  }
}
}
