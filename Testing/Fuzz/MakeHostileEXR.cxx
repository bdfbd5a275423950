// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// Write the generated hostile OpenEXR files (Testing/Support/vtkBloomHostileEXR.cxx) into a
// directory: seeds for the fuzz target, and inputs for scripts that try the tool on them.
//   MakeHostileEXR DIRECTORY
#include "vtkBloomHostileEXR.h"

#include <iostream>

int main(int argc, char* argv[])
{
  if (argc != 2)
  {
    std::cerr << "usage: MakeHostileEXR DIRECTORY\n";
    return 2;
  }
  const auto paths = vtkBloomHostileEXR::WriteAll(argv[1]);
  std::cout << paths.size() << " hostile files written to " << argv[1] << "\n";
  return 0;
}
