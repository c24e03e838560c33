// Random mutations of the example problems and of the seeds of
// tests/cpp/problem/fuzz_corpus (the key families the examples lack: tubes
// from a table's slices and gates, headings, heading windows, p_implies_z,
// scheduling, every [output] key): the loader never crashes nor hangs; it
// returns a problem or throws a ProblemError that starts with the file name
// and its line and column. A problem that loads is also built and solved on a
// coarse slicing: no other exception than sillage::Error.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <cstring>
#include <random>
#include <regex>

#include "problem_text.h"
#include "sillage/problem/solve_problem.h"

using namespace sillage;

namespace {

// file:line:column: found
const std::regex kLineColumn(R"(^\S+\.toml:[0-9]+:[0-9]+: found )");

const char* kAlphabet = "[]{}=\",.#-+*/()_ \nabcxyzt0123456789";

std::string mutate(std::string s, std::mt19937& rng) {
  const int n = 1 + static_cast<int>(rng() % 4);
  for (int m = 0; m < n && !s.empty(); ++m) {
    const std::size_t i = rng() % s.size();
    switch (rng() % 6) {
      case 0: s.erase(i, 1 + rng() % 8); break;                                  // delete a run
      case 1: s.insert(i, 1, kAlphabet[rng() % std::strlen(kAlphabet)]); break;  // insert a character
      case 2: s[i] = kAlphabet[rng() % std::strlen(kAlphabet)]; break;           // replace one
      case 3: {                                                                  // duplicate a line
        const std::size_t b = s.rfind('\n', i), e = s.find('\n', i);
        const std::size_t from = b == std::string::npos ? 0 : b + 1, to = e == std::string::npos ? s.size() : e;
        s.insert(from, s.substr(from, to - from) + "\n");
        break;
      }
      case 4: {  // a digit becomes another number
        const std::size_t d = s.find_first_of("0123456789", i);
        if (d != std::string::npos) s.replace(d, 1, std::to_string(static_cast<int>(rng() % 2000) - 1000));
        break;
      }
      default: s = s.substr(0, i); break;  // truncate
    }
  }
  return s;
}

// The example problems and the fuzz seeds, in a fixed order.
std::vector<std::string> corpus() {
  std::vector<std::filesystem::path> files;
  for (const std::string& dir : {problem_test::problems_dir(), std::string(SILLAGE_SOURCE_DIR) + "/tests/cpp/problem/fuzz_corpus"})
    for (const auto& e : std::filesystem::directory_iterator(dir))
      if (e.path().extension() == ".toml") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  std::vector<std::string> texts;
  for (const auto& f : files) texts.push_back(problem_test::read_file(f.string()));
  return texts;
}

}  // namespace

// The mutator starts from valid files that hold every key family.
TEST(ProblemFuzz, CorpusLoadsAndHoldsEveryKeyFamily) {
  std::string all;
  for (const std::string& text : corpus()) {
    all += text;
    // Each is a valid problem, but for data that lives outside the repository
    // (plaza1's shared folder, the survey's tables written by the build).
    const std::string error = problem_test::error_of(text);
    EXPECT_TRUE(error.empty() || error.find("cannot open") != std::string::npos) << error;
  }
  for (const char* key : {"points = {", "slices = {", "gates = {", "at = [", "\"p_implies_z\"", "\"heading\"",
                          "\"heading_window\"", "\"second_deriv\"", "\"increment\"", "\"eval\"", "where =", "join =",
                          "gates = true", "outside =", "time_error", "scheduling =", "order =", "ratio =", "loops = {", "landmarks =",
                          "truth = {", "maps =", "plots =", "\"interval\"", "\"box\"", "stride =", "turn_accel ="})
    EXPECT_NE(all.find(key), std::string::npos) << key;
}

TEST(ProblemFuzz, MutatedExamplesLoadOrFailClearly) {
  const std::vector<std::string> texts = corpus();
  ASSERT_GE(texts.size(), 3u);
  std::mt19937 rng(20261124);
  std::size_t loaded = 0, rejected = 0;
  for (int iter = 0; iter < 1500; ++iter) {
    const std::string text = mutate(texts[iter % texts.size()], rng);
    try {
      const Problem p = problem_test::parse(text);
      ++loaded;
      SolveOptions o;
      o.delta = (p.time.tf - p.time.t0) / 50;
      try {
        (void)solve_problem(p, o);
      } catch (const Error&) {
        // a bound that evaluates to nothing usable, a row outside: reported, not crashed
      }
    } catch (const ProblemError& e) {
      ++rejected;
      const std::string msg = e.what();
      ASSERT_EQ(msg.rfind(problem_test::problems_dir() + "/test.toml:", 0), 0u) << msg << "\n--- text:\n" << text;
      ASSERT_TRUE(std::regex_search(msg, kLineColumn)) << msg << "\n--- text:\n" << text;
      ASSERT_NE(msg.find("expected"), std::string::npos) << msg;
    }
  }
  EXPECT_GT(rejected, 100u);
  EXPECT_GT(loaded, 10u);
}
