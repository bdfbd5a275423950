// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkBloomToolData.h"

#include <vtkCompositeDataIterator.h>
#include <vtkCompositeDataSet.h>
#include <vtkDataSet.h>
#include <vtkGenericDataObjectReader.h>
#include <vtkLogger.h>
#include <vtkNew.h>
#include <vtkOutputWindow.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>
#include <vtkXMLGenericDataObjectReader.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <regex>

namespace fs = std::filesystem;

namespace vtkBloomTool
{
namespace
{
const char* const DatasetExtensions[] = { ".vti", ".vtu", ".vtp", ".vts", ".vtr", ".vtm", ".vtk" };

bool IsDataExtension(const std::string& extension)
{
  return std::find(std::begin(DatasetExtensions), std::end(DatasetExtensions), extension) !=
    std::end(DatasetExtensions);
}

// %d or %0Nd in a file name: a numbered series.
const std::regex NumberPattern("%(0[1-9][0-9]*)?d");
}

//------------------------------------------------------------------------------
void ForEachDataSet(vtkDataObject* data, const std::function<void(vtkDataSet*)>& visit)
{
  if (auto* dataset = vtkDataSet::SafeDownCast(data))
  {
    visit(dataset);
  }
  else if (auto* composite = vtkCompositeDataSet::SafeDownCast(data))
  {
    vtkSmartPointer<vtkCompositeDataIterator> it;
    it.TakeReference(composite->NewIterator());
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    {
      if (auto* leaf = vtkDataSet::SafeDownCast(it->GetCurrentDataObject()))
      {
        visit(leaf);
      }
    }
  }
}

//------------------------------------------------------------------------------
bool IsDatasetPath(const std::string& path)
{
  const std::string extension = Extension(path);
  return extension == ".pvd" || IsDataExtension(extension);
}

//------------------------------------------------------------------------------
DatasetFiles ResolveDataset(const std::string& path)
{
  DatasetFiles result;
  const std::string extension = Extension(path);
  std::error_code ec;
  const std::string name = fs::path(path).filename().string();
  if (std::regex_search(name, NumberPattern))
  {
    // A numbered series: every file of the directory whose name matches, consecutive.
    fs::path directory = fs::path(path).parent_path();
    if (directory.empty())
    {
      directory = ".";
    }
    std::string expression;
    std::smatch match;
    std::string rest = name;
    while (std::regex_search(rest, match, NumberPattern))
    {
      expression +=
        std::regex_replace(match.prefix().str(), std::regex(R"([.^$|()\[\]{}*+?\\])"), R"(\$&)");
      expression += match[1].matched ? "([0-9]{" + match[1].str().substr(1) + ",})" : "([0-9]+)";
      rest = match.suffix().str();
    }
    expression += std::regex_replace(rest, std::regex(R"([.^$|()\[\]{}*+?\\])"), R"(\$&)");
    const std::regex filePattern(expression);
    std::map<long, std::string> steps;
    for (const auto& entry : fs::directory_iterator(directory, ec))
    {
      const std::string candidate = entry.path().filename().string();
      std::smatch m;
      if (entry.is_regular_file(ec) && std::regex_match(candidate, m, filePattern))
      {
        steps[std::stol(m[1].str())] = entry.path().string();
      }
    }
    if (ec || steps.empty())
    {
      throw RunError{ "no file matches the pattern " + path };
    }
    long expected = steps.begin()->first;
    for (const auto& step : steps)
    {
      if (step.first != expected)
      {
        throw RunError{ "the series " + path + " is missing step " + std::to_string(expected) +
          " (it has " + std::to_string(steps.begin()->first) + " to " +
          std::to_string(steps.rbegin()->first) + ")" };
      }
      ++expected;
      result.Files.push_back(step.second);
      result.Times.push_back(static_cast<double>(step.first));
    }
    return result;
  }
  if (!fs::exists(path, ec))
  {
    throw RunError{ "cannot read " + path + ": no such file" };
  }
  if (fs::is_directory(path, ec))
  {
    throw RunError{ "cannot read " + path + ": is a directory" };
  }
  if (extension == ".pvd")
  {
    // A ParaView collection: <VTKFile type="Collection"><Collection><DataSet timestep= file=/>.
    // VTK 9.1 ships no .pvd reader, so it is read with VTK's own XML parser.
    vtkNew<vtkXMLDataParser> parser;
    ErrorCollector errors;
    errors.Watch(parser);
    parser->SetFileName(path.c_str());
    vtkXMLDataElement* root = parser->Parse() ? parser->GetRootElement() : nullptr;
    vtkXMLDataElement* collection = root ? root->FindNestedElementWithName("Collection") : nullptr;
    const char* type = root ? root->GetAttribute("type") : nullptr;
    if (!collection || !type || std::string(type) != "Collection")
    {
      throw RunError{ "cannot read " + path + ": not a VTK collection (.pvd) file" };
    }
    std::vector<std::pair<double, std::string>> steps;
    for (int i = 0; i < collection->GetNumberOfNestedElements(); ++i)
    {
      vtkXMLDataElement* dataset = collection->GetNestedElement(i);
      const char* file = dataset->GetAttribute("file");
      if (std::string(dataset->GetName()) != "DataSet" || !file)
      {
        continue;
      }
      double time = static_cast<double>(steps.size());
      dataset->GetScalarAttribute("timestep", time);
      fs::path step(file);
      if (step.is_relative())
      {
        step = fs::path(path).parent_path() / step;
      }
      steps.emplace_back(time, step.string());
    }
    if (steps.empty())
    {
      throw RunError{ "cannot read " + path + ": the collection lists no DataSet" };
    }
    std::stable_sort(
      steps.begin(), steps.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    for (size_t i = 0; i < steps.size(); ++i)
    {
      if (i > 0 && steps[i].first == steps[i - 1].first)
      {
        throw RunError{ "cannot read " + path +
          ": several parts per time step are not supported (time " +
          std::to_string(steps[i].first) + ")" };
      }
      if (!fs::is_regular_file(steps[i].second, ec))
      {
        throw RunError{ "cannot read " + path + ": time step " + std::to_string(i) + " (time " +
          std::to_string(steps[i].first) + ") names " + steps[i].second +
          ", which does not exist" };
      }
      result.Files.push_back(steps[i].second);
      result.Times.push_back(steps[i].first);
    }
    return result;
  }
  if (!IsDataExtension(extension))
  {
    throw RunError{ "cannot read " + path + ": unknown extension '" + extension +
      "' (expected .vti, .vtu, .vtp, .vts, .vtr, .vtm, .vtk or .pvd)" };
  }
  result.Files.push_back(path);
  result.Times.push_back(0.0);
  return result;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkDataObject> ReadDataset(const std::string& file, ErrorCollector& errors)
{
  // The readers make inner readers and parsers of their own, whose errors reach only the
  // output window: collect those too, and keep them off the terminal.
  // VTK's logger writes them to stderr as well, before our message: off while reading.
  vtkOutputWindow* window = vtkOutputWindow::GetInstance();
  const int mode = window->GetDisplayMode();
  window->SetDisplayModeToNever();
  const vtkLogger::Verbosity verbosity = vtkLogger::GetCurrentVerbosityCutoff();
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  const unsigned long tag = errors.Watch(window);
  vtkSmartPointer<vtkDataObject> data;
  if (Extension(file) == ".vtk")
  {
    vtkNew<vtkGenericDataObjectReader> reader;
    errors.Watch(reader);
    reader->SetFileName(file.c_str());
    if (reader->OpenVTKFile() && reader->ReadHeader())
    {
      reader->CloseVTKFile();
      reader->Update();
      data = reader->GetOutput();
    }
    else
    {
      reader->CloseVTKFile();
      errors.Messages.push_back("not a legacy VTK file");
    }
  }
  else
  {
    vtkNew<vtkXMLGenericDataObjectReader> reader;
    errors.Watch(reader);
    reader->SetFileName(file.c_str());
    reader->Update();
    data = reader->GetOutputDataObject(0);
  }
  window->RemoveObserver(tag);
  window->SetDisplayMode(mode);
  vtkLogger::SetStderrVerbosity(verbosity);
  errors.ThrowIfAny("cannot read " + file + ":");
  if (!data)
  {
    throw RunError{ "cannot read " + file + ": not a VTK data file" };
  }
  vtkIdType points = 0;
  ForEachDataSet(data, [&points](vtkDataSet* dataset) { points += dataset->GetNumberOfPoints(); });
  if (points == 0)
  {
    throw RunError{ "cannot render " + file + ": the dataset is empty (no points)" };
  }
  return data;
}
}
