// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// Hostile OpenEXR files, written byte by byte: valid-looking headers that claim what their
// bytes cannot hold (huge data windows backed by a few hundred bytes, chunk tables that point
// outside the file, impossible tile and level layouts, deep and multi-part variants), one set
// for every compression. A reader must refuse each of them quickly, with a clear error, in
// memory bounded by the file. Used by TestOpenEXRHostile, TestCommandLine and, as seeds, by
// the fuzz target (Testing/Fuzz).
#ifndef vtkBloomHostileEXR_h
#define vtkBloomHostileEXR_h

#include <ostream>
#include <string>
#include <vector>

namespace vtkBloomHostileEXR
{
struct File
{
  std::string Name;        // a file name, unique, ending in .exr
  std::string Description; // what is wrong with it
  std::vector<unsigned char> Bytes;
};

/// For GoogleTest's parameter names.
void PrintTo(const File& file, std::ostream* os);

/// Every hostile file, deterministically generated.
std::vector<File> MakeAll();

/// Write MakeAll() into `directory` (created when missing); returns the paths written.
std::vector<std::string> WriteAll(const std::string& directory);
}

#endif
