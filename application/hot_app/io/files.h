// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_FILES_H
#define CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_FILES_H

// Files for the tool's readers: a file checked readable and read whole into memory (with
// a one-line reason when it cannot be), and the lowercase extension of a file name.

#include "common.h"

#include <cstdint>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

#include <CGAL/disable_warnings.h>

/// \file files.h

namespace hot_tools {

/// the file exists, is a regular file and can be opened
inline HOT::Status check_readable_file(const std::string& path)
{
  if(path.empty())
    return io_impl::read_fail("no file name given");
  std::error_code ec;
  const std::filesystem::file_status st = std::filesystem::status(path, ec);
  if(ec || !std::filesystem::exists(st))
    return io_impl::read_fail("'" + path + "': no such file");
  if(std::filesystem::is_directory(st))
    return io_impl::read_fail("'" + path + "' is a directory, not a file");
  if(!std::filesystem::is_regular_file(st))
    return io_impl::read_fail("'" + path + "' is not a regular file");
  std::ifstream in(path, std::ios::binary);
  if(!in)
    return io_impl::read_fail("'" + path + "': cannot open the file for reading (permission denied?)");
  return HOT::Status();
}

/// reads the whole file `path` into `data` (a missing file, a directory etc. get their own reason)
inline HOT::Status read_file_contents(const std::string& path, std::string& data)
{
  data.clear();
  HOT::Status r = check_readable_file(path);
  if(!r)
    return r;
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if(ec)
    return io_impl::read_fail("'" + path + "': cannot get the file size (" + ec.message() + ")");
  std::ifstream in(path, std::ios::binary);
  if(!in)
    return io_impl::read_fail("'" + path + "': cannot open the file for reading (permission denied?)");
  try {
    data.resize(static_cast<std::size_t>(size));
  } catch(const std::exception&) {
    return io_impl::read_fail("'" + path + "': the file is too large to be read into memory");
  }
  if(size > 0 && !in.read(&data[0], static_cast<std::streamsize>(size)))
    return io_impl::read_fail("'" + path + "': read error");
  return HOT::Status();
}

/// the extension of the file name of `path`, in lowercase, without the dot (empty if none)
inline std::string file_extension(const std::string& path)
{
  const std::string name = std::filesystem::path(path).filename().string();
  const std::size_t dot = name.rfind('.');
  if(dot == std::string::npos || dot == 0)
    return std::string();
  return io_impl::lowercase(name.substr(dot + 1));
}

} // namespace hot_tools

#include <CGAL/enable_warnings.h>

#endif // CGAL_HYPERBOLIC_ORBIFOLD_TUTTE_TOOLS_IO_FILES_H
