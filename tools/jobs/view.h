// Copyright (c) 2026  The Hyperbolic_orbifold_Tutte project.  All rights reserved.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s)     : Hyperbolic_orbifold_Tutte developers

#ifndef HOT_TOOLS_JOBS_VIEW_H
#define HOT_TOOLS_JOBS_VIEW_H

// The `view` command: a folder to open in a browser (hot_app/view.h writes it) showing a stored
// embedding, the map between two stored embeddings, or a collection's embeddings and maps.

#include "command_line.h"
#include "hot_app/stored_embedding.h"
#include "hot_app/view.h"

#include <iostream>
#include <string>
#include <vector>

namespace hot_cli {

// `view --embedding E.obj | --source-embedding A.obj --target-embedding B.obj | --collection DIR --out OUT`
inline int run_view(int argc, char** argv)
{
  const Options opt(argc, argv, 2, {"embedding", "source-embedding", "target-embedding", "collection", "out"});
  const std::string out = opt.get("out");
  const int forms = int(opt.has("embedding")) + int(opt.has("source-embedding") || opt.has("target-embedding")) + int(opt.has("collection"));
  if(forms != 1)
    throw Usage_error{"give one of --embedding E.obj, --source-embedding A.obj --target-embedding B.obj, --collection DIR"};
  std::vector<std::string> paths;
  std::string kind, title;
  if(opt.has("embedding")) {
    paths.push_back(opt.get("embedding"));
    kind = "embedding";
  } else if(opt.has("collection")) {
    paths = collection_embeddings(opt.get("collection"));
    kind = "collection";
    title = "collection " + view_impl::file_name(opt.get("collection"));
  } else {
    if(!opt.has("source-embedding") || !opt.has("target-embedding"))
      throw Usage_error{"--source-embedding and --target-embedding go together"};
    paths = {opt.get("source-embedding"), opt.get("target-embedding")};
    kind = "map";
    title = view_impl::file_name(paths[0]) + " -> " + view_impl::file_name(paths[1]);
  }
  std::vector<Stored_embedding> E(paths.size());
  std::vector<Locator> L;
  L.reserve(paths.size()); // (the inputs point to them)
  for(std::size_t i = 0; i < paths.size(); ++i) {
    read_stored_embedding(paths[i], E[i], kind != "embedding"); // (one embedding of genus g >= 1: drawn without its tiling)
    if(i > 0)
      check_stored_pair(E[0], E[i]);
  }
  std::vector<View_input> in;
  for(const Stored_embedding& e : E) {
    if(e.cones.genus == 0)
      L.push_back(stored_locator(e));
    in.push_back(view_input(e, e.cones.genus == 0 ? &L.back() : nullptr));
  }
  const View_data d = kind == "embedding" ? view_embedding(in[0]) : view_maps(in, kind, title);
  write_view_folder(out, d);
  std::size_t unreliable = 0;
  for(const View_map& m : d.maps)
    if(m.from == 0) unreliable += m.unreliable.size();
  std::cout << "wrote " << out << "/index.html (" << d.shapes.size() << (d.shapes.size() == 1 ? " shape" : " shapes")
            << (unreliable ? ", " + std::to_string(unreliable) + " unreliable images marked" : std::string()) << ")" << std::endl;
  return EXIT_SUCCESS;
}

} // namespace hot_cli

#endif // HOT_TOOLS_JOBS_VIEW_H
