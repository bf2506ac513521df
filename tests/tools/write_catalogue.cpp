// Writes every case of the scene catalogues as one file, OUT_DIR/seed-N.json,
// N counting the cases in the order given: the fuzzer's seed corpus, and the
// scenes the Python module's test reduces. Usage: write_catalogue OUT_DIR
// CATALOGUE.json...
#include <fstream>
#include <iostream>

#include "catalogue.hpp"

int main(int argc, char** argv) {
  if (argc < 3) {
    std::cerr << "usage: write_catalogue OUT_DIR CATALOGUE.json...\n";
    return 2;
  }
  const nlohmann::json base = nlohmann::json::parse(pendulum::test::nelson_olsson_text());
  int n = 0;
  for (int i = 2; i < argc; ++i) {
    const auto catalogue = nlohmann::json::parse(pendulum::test::read_text(argv[i]));
    for (const auto& entry : catalogue.at("cases")) {
      std::ofstream(std::string(argv[1]) + "/seed-" + std::to_string(n++) + ".json",
                    std::ios::binary)
          << pendulum::test::catalogue_text(entry, catalogue.value("base", base));  // student_slips has its own
    }
  }
  return 0;
}
