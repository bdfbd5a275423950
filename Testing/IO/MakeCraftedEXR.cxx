// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// Write the crafted OpenEXR files (Testing/Support/vtkBloomCraftedEXR.h) into a directory, with
// a README that says what is wrong with each. The committed set in Testing/Data/EXR/Crafted was
// written by this tool against OpenEXR 3.1.5:
//   build/bin/MakeCraftedEXR Testing/Data/EXR/Crafted
#include "vtkBloomCraftedEXR.h"

#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>

int main(int argc, char* argv[])
{
  if (argc != 2)
  {
    std::cerr << "usage: MakeCraftedEXR DIRECTORY\n";
    return 2;
  }
  try
  {
    const std::string directory = argv[1];
    const auto scratch = std::filesystem::temp_directory_path() / "vtkbloom-crafted-valid";
    const auto files = vtkBloomCraftedEXR::MakeAll(scratch.string());
    vtkBloomCraftedEXR::WriteAll(files, directory);
    // The sound files they come from: seeds that lead the fuzz target into DWA, tiled and
    // luminance/chroma decoding.
    vtkBloomCraftedEXR::WriteAll(
      vtkBloomCraftedEXR::MakeValid(scratch.string()), directory + "/valid");
    std::ofstream readme(directory + "/README.md", std::ios::trunc);
    readme << "# Crafted OpenEXR files\n\n"
           << "Written by `MakeCraftedEXR` (Testing/IO/MakeCraftedEXR.cxx) from valid files of "
              "OpenEXR's C++ library, one chunk's streams rewritten to decode short of what "
              "the header and channel list require. Every file must be refused with one line "
              "naming the chunk and the sizes. `valid/` holds the sound files they come from.\n\n"
              "| file | damage |\n|---|---|\n";
    for (const auto& file : files)
    {
      readme << "| " << file.Name << " | " << file.Description << " |\n";
    }
    std::cout << files.size() << " crafted files written to " << directory << "\n";
    return 0;
  }
  catch (const std::exception& e)
  {
    std::cerr << "MakeCraftedEXR: " << e.what() << "\n";
    return 1;
  }
}
