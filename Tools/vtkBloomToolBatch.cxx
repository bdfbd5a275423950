// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkBloomToolBatch.h"

#include "vtkBloomToolImageIO.h"
#include "vtkBloomToolSupport.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <set>
#include <sstream>
#include <system_error>

namespace fs = std::filesystem;

namespace vtkBloomTool
{
//------------------------------------------------------------------------------
FileJob PlanSingle(const std::string& input, const std::string& output)
{
  const std::string ext = Extension(output);
  if (ext != ".exr" && ext != ".png")
  {
    throw UsageError{ "output must end in .exr or .png: " + output };
  }
  std::error_code ec;
  if (!fs::exists(input, ec))
  {
    throw RunError{ "cannot read " + input + ": no such file" };
  }
  if (fs::exists(output, ec) && fs::equivalent(input, output, ec))
  {
    throw UsageError{ "refusing to overwrite the input " + input + " with the output" };
  }
  if (fs::is_directory(output, ec))
  {
    throw RunError{ "output " + output + " is a directory" };
  }
  return { input, output, "" };
}

//------------------------------------------------------------------------------
std::vector<FileJob> PlanBatch(const std::vector<std::string>& inputs, const std::string& directory,
  const std::string& extension)
{
  std::error_code ec;
  if (fs::exists(directory, ec) && !fs::is_directory(directory, ec))
  {
    throw RunError{ "-o " + directory + " exists and is not a directory" };
  }
  fs::create_directories(directory, ec);
  if (ec)
  {
    throw RunError{ "cannot create the output directory " + directory + ": " + ec.message() };
  }
  std::vector<FileJob> jobs;
  std::set<std::string> outputs;
  for (const std::string& input : inputs)
  {
    FileJob job;
    job.Input = input;
    job.Output = (fs::path(directory) / fs::path(input).stem()).string() + extension;
    if (!fs::exists(input, ec))
    {
      job.Problem = "cannot read " + input + ": no such file";
    }
    else if (fs::is_directory(input, ec))
    {
      job.Problem = "cannot read " + input + ": is a directory";
    }
    else if (!outputs.insert(job.Output).second)
    {
      job.Problem = "not processed: " + input + " would write " + job.Output +
        ", which an earlier input of the same name writes";
    }
    else if (fs::exists(job.Output, ec) || fs::is_symlink(job.Output, ec))
    {
      job.Problem = "not processed: the output " + job.Output +
        " already exists and batch mode never overwrites a file";
    }
    jobs.push_back(job);
  }
  return jobs;
}

namespace
{
//------------------------------------------------------------------------------
std::string Quoted(const std::string& text)
{
  std::string out = "\"";
  for (const char c : text)
  {
    const auto u = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\')
    {
      out += '\\';
      out += c;
    }
    else if (u < 0x20)
    {
      char escape[8];
      std::snprintf(escape, sizeof(escape), "\\u%04x", u);
      out += escape;
    }
    else
    {
      out += c;
    }
  }
  return out + "\"";
}

//------------------------------------------------------------------------------
std::string Number(double value)
{
  if (!std::isfinite(value))
  {
    return "null";
  }
  std::ostringstream s;
  s.precision(17);
  s << value;
  return s.str();
}
}

//------------------------------------------------------------------------------
void WriteStatistics(
  const std::string& path, const std::string& command, const std::vector<FileReport>& reports)
{
  std::ostringstream json;
  json << "{\n  \"command\": " << Quoted(command) << ",\n  \"files\": [";
  for (size_t i = 0; i < reports.size(); ++i)
  {
    const FileReport& r = reports[i];
    json << (i ? "," : "") << "\n    {\"input\": " << Quoted(r.Input)
         << ", \"output\": " << Quoted(r.Output)
         << ", \"status\": " << (r.Succeeded ? "\"ok\"" : "\"error\"");
    if (!r.Succeeded)
    {
      json << ", \"error\": " << Quoted(r.Error);
    }
    json << ", \"seconds\": " << Number(r.Seconds);
    if (r.Succeeded)
    {
      json << ", \"width\": " << r.Width << ", \"height\": " << r.Height;
    }
    if (r.Succeeded && r.HasBloomStatistics)
    {
      json << ", \"exact\": " << (r.Exact ? "true" : "false")
           << ", \"bloom_skipped\": " << (r.BloomSkipped ? "true" : "false")
           << ", \"energy_in\": " << Number(r.EnergyIn)
           << ", \"energy_out\": " << Number(r.EnergyOut)
           << ", \"bright_pixels\": " << r.NumberOfBrightPixels
           << ", \"peak_luminance_in\": " << Number(r.PeakLuminanceIn)
           << ", \"peak_luminance_out\": " << Number(r.PeakLuminanceOut)
           << ", \"levels_used\": " << r.NumberOfLevelsUsed;
    }
    json << "}";
  }
  json << "\n  ]\n}\n";
  const std::string text = json.str();
  WriteFileAtomically(path, reinterpret_cast<const unsigned char*>(text.data()), text.size());
}
}
