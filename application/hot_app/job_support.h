// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef HOT_APP_JOB_SUPPORT_H
#define HOT_APP_JOB_SUPPORT_H

// What every job of the application layer (the command line's and the Python module's) uses:
// its data failure (Failure: an Error_code and a one-line reason; the command line ends with
// status 3, the Python module raises its error), output files written atomically (a
// temporary name renamed only when complete; a failed job removes those it already wrote:
// Output_files), and the fewest landmarks a landmark file may hold.

#include <CGAL/Hyperbolic_orbifold_Tutte/error_code.h>
#include <CGAL/Hyperbolic_orbifold_Tutte/check_input.h> // minimum_number_of_landmarks

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace hot_cli {

namespace HOT = CGAL::Hyperbolic_orbifold_Tutte;

struct Failure
{
  HOT::Error_code code;
  std::string message;
};

// throws a failed check's reason
inline void require(const HOT::Status& r)
{
  if(!r)
    throw Failure{r.code, r.message};
}

// Writes a file atomically: the content goes to FILE.tmp, renamed to FILE on success. A failed
// write (disk full, file size limit, unwritable folder) throws one line naming the file and the
// system's reason, with FILE.tmp removed and FILE untouched: the stream's state is checked
// after the last byte and after closing, before the rename. SIGXFSZ (a file size limit,
// `ulimit -f`) is ignored so that such a write fails with EFBIG instead of killing the process.
// A process killed while writing leaves at most FILE.tmp, never a truncated FILE.
inline void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& writer)
{
  static const bool xfsz_ignored = (std::signal(SIGXFSZ, SIG_IGN), true);
  (void)xfsz_ignored;
  const std::string tmp = path + ".tmp";
  auto fail = [&](const char* what, int err) {
    std::remove(tmp.c_str());
    throw std::runtime_error(std::string(what) + " '" + path + "'" + (err != 0 ? std::string(": ") + std::strerror(err) : std::string()));
  };
  {
    errno = 0;
    std::ofstream out(tmp, std::ios::out | std::ios::trunc | std::ios::binary);
    if(!out)
      fail("cannot write", errno);
    errno = 0;
    try {
      writer(out);
    } catch(...) {
      out.close();
      std::remove(tmp.c_str());
      throw;
    }
    out.flush();
    if(!out) {
      const int err = errno;
      out.close();
      fail("error while writing", err);
    }
    out.close();
    if(out.fail())
      fail("error while writing", errno);
  }
  if(std::rename(tmp.c_str(), path.c_str()) != 0)
    fail("cannot write", errno);
}

// The output files of a command, each written atomically. Unless commit() is called, the
// destructor removes those already written: a command that fails leaves no output file.
class Output_files
{
public:
  Output_files() = default;
  Output_files(const Output_files&) = delete;
  Output_files& operator=(const Output_files&) = delete;
  ~Output_files()
  {
    for(const std::string& f : written_)
      std::remove(f.c_str());
  }
  void write(const std::string& path, const std::function<void(std::ostream&)>& writer)
  {
    write_file_atomically(path, writer);
    written_.push_back(path);
  }
  void commit() { written_.clear(); }

private:
  std::vector<std::string> written_;
};

// the fewest landmarks a landmark file may hold: 5, or 3 with cone orders
inline std::size_t minimum_landmarks(const std::vector<int>& orders)
{
  return orders.empty() ? HOT::minimum_number_of_landmarks : 3;
}

} // namespace hot_cli

#endif // HOT_APP_JOB_SUPPORT_H
