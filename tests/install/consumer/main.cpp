// Tone-maps an EXR with the installed library, as `cgtmo apply IN -o OUT --op OP` does.
// Usage: consumer IN.exr OUT.png OPERATOR
#include <iostream>

#include "cgtmo/errors.h"
#include "cgtmo/operators/registry.h"
#include "cgtmo/pipeline/apply_file.h"
#include "cgtmo/util/parallel.h"
#include "cgtmo/util/version.h"

int main(int argc, char** argv) {
  if (argc != 4) {
    std::cerr << "usage: consumer IN.exr OUT.png OPERATOR\n";
    return 2;
  }
  try {
    cgtmo::set_threads(2);
    cgtmo::pipeline::ApplyOptions options;
    options.op = argv[3];
    const cgtmo::pipeline::Applier applier(options);
    const cgtmo::pipeline::ApplyReport report = applier.apply_file(argv[1], argv[2]);
    std::cout << "cgtmo " << cgtmo::version() << ", " << cgtmo::operators::registry().size() << " operators; "
              << report.width << "x" << report.height << " " << report.tonemap.op->name << " -> " << report.display
              << "/" << report.view << "\n";
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "consumer: error: " << e.what() << "\n";
    return 1;
  }
}
