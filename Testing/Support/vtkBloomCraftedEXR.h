// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// Crafted OpenEXR files: valid files written by OpenEXR's C++ library, then one chunk's
// streams rewritten so that they decode to fewer bytes or values than the header and channel
// list require, while every size the file states stays consistent with its streams. OpenEXR
// 3.1 accepts such DWA chunks and copies its unset buffer bytes into the image; a reader must
// refuse each one. The set covers DWAA and DWAB with short UNKNOWN, RLE, AC and DC streams,
// tiled DWA, luminance/chroma (Y, RY, BY) DWA, and short streams of RLE, ZIPS and ZIP, plain
// and luminance/chroma.
//
// MakeCraftedEXR (Testing/Fuzz) writes them into Testing/Data/EXR/Crafted, where the tests,
// the command-line tests under valgrind and the fuzz target's seeds read them; the suite also
// regenerates them with the OpenEXR it is built against.
#ifndef vtkBloomCraftedEXR_h
#define vtkBloomCraftedEXR_h

#include <string>
#include <vector>

namespace vtkBloomCraftedEXR
{
struct File
{
  std::string Name;        // unique, ending in .exr
  std::string Description; // what is wrong with it
  std::vector<unsigned char> Bytes;
};

/// Every crafted file. Throws std::runtime_error when a valid file cannot be written or
/// parsed. `scratch` is a directory for the valid files written on the way.
std::vector<File> MakeAll(const std::string& scratch);

/// The valid files the crafted ones are made from (same names without the damage): each must
/// read exactly as OpenEXR's C++ library decodes it.
std::vector<File> MakeValid(const std::string& scratch);

/// Write `files` into `directory` (created when missing); returns the paths written.
std::vector<std::string> WriteAll(const std::vector<File>& files, const std::string& directory);
}

#endif
