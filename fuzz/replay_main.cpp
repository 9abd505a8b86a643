// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A replay driver for a libFuzzer target where libFuzzer is not available (g++): feeds each
// file given, and each file of each directory given (sorted by name), to
// LLVMFuzzerTestOneInput() once, as `fuzzer -runs=0 DIR` does with libFuzzer. The target
// aborts on a broken contract (and the sanitizers, when built with them, on any error):
// the replay then stops, and a signal handler names the input on stderr. Exits with status 1 if it found
// no input at all (a replay of nothing checks nothing), 0 after every input ran.
//   fuzz_mesh_reader [--min-inputs N] FILE_OR_DIR...

#include <algorithm>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

#include <unistd.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

char current_input[4096]; // the input being replayed, for the signal handler

extern "C" void name_the_input(int sig)
{
  const char head[] = "\nreplay: the input that failed: ";
  (void)!write(2, head, sizeof(head) - 1);
  (void)!write(2, current_input, std::strlen(current_input));
  (void)!write(2, "\n", 1);
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

} // namespace

int main(int argc, char** argv)
{
  std::signal(SIGABRT, name_the_input); // (not SIGSEGV: the sanitizers' own handlers report those)
  namespace fs = std::filesystem;
  std::vector<fs::path> inputs;
  std::size_t min_inputs = 1;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if(a == "--min-inputs" && i + 1 < argc) {
      min_inputs = std::strtoul(argv[++i], nullptr, 10);
      continue;
    }
    const fs::path p(a);
    std::error_code ec;
    if(fs::is_directory(p, ec)) {
      std::vector<fs::path> files;
      for(const fs::directory_entry& e : fs::directory_iterator(p))
        if(e.is_regular_file())
          files.push_back(e.path());
      std::sort(files.begin(), files.end());
      inputs.insert(inputs.end(), files.begin(), files.end());
    } else if(fs::is_regular_file(p, ec)) {
      inputs.push_back(p);
    } else {
      std::cerr << "replay: no file or directory " << p << std::endl;
      return EXIT_FAILURE;
    }
  }
  if(inputs.size() < min_inputs) {
    std::cerr << "replay: " << inputs.size() << " inputs found, fewer than the " << min_inputs << " expected" << std::endl;
    return EXIT_FAILURE;
  }
  std::size_t bytes = 0;
  for(const fs::path& p : inputs) {
    std::ifstream in(p, std::ios::binary);
    const std::vector<char> data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if(!in.eof() && in.fail()) {
      std::cerr << "replay: cannot read " << p << std::endl;
      return EXIT_FAILURE;
    }
    const std::string name = p.string();
    std::snprintf(current_input, sizeof(current_input), "%s", name.c_str());
    LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(data.data()), data.size());
    bytes += data.size();
  }
  std::cout << "replayed " << inputs.size() << " inputs (" << bytes << " bytes): no contract broken" << std::endl;
  return EXIT_SUCCESS;
}
