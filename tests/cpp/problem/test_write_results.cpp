// results.json written as text (write_results.cpp): valid JSON whose bounds
// are the domains' doubles exactly; null for an infinite bound and for an
// empty interval; intervals and boxes as "value".
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "problem_text.h"
#include "sillage/problem/solve_problem.h"
#include "sillage/problem/write_results.h"

using namespace sillage;

TEST(WriteResults, BoundsExactlyNullsForInfinitiesAndEmpties) {
  const Problem p = problem_test::parse(
      "[time]\ndomain = [0, 1]\ndelta = 0.25\n"
      "[var.x]\nkind = \"tube\"\nvalue = \"[0, 1]/3\"\n"
      "[var.u]\nkind = \"tube\"\n"
      "[var.a]\nkind = \"interval\"\nvalue = \"[1, 2]\"\n"
      "[var.b]\nkind = \"box\"\ndim = 2\nvalue = [\"[0, 1]\", \"[2, 3]\"]\n"
      "[[constraint]]\nkind = \"expr\"\nexpr = \"a - 1.5 - 0*b[0]\"\n");
  SolveResult r = solve_problem(p);
  ASSERT_FALSE(r.empty) << r.why_empty;
  (*r.built.var("x").tubes)[0].set(Interval::empty(), 1);  // as a writer may meet it
  const std::string text = results_json(p, r);
  const auto j = nlohmann::json::parse(text);
  const Tube& x = (*r.built.var("x").tubes)[0];
  const auto& jx = j["variables"]["x"]["components"][0];
  ASSERT_EQ(jx["gates"].size(), x.nb_slices() + 1);
  for (std::size_t k = 0; k <= x.nb_slices(); ++k) {
    if (x.gate(k).is_empty()) {  // the gates of the emptied slice
      EXPECT_TRUE(jx["gates"][k].is_null()) << k;
      continue;
    }
    EXPECT_EQ(jx["gates"][k][0].get<double>(), x.gate(k).lb());
    EXPECT_EQ(jx["gates"][k][1].get<double>(), x.gate(k).ub());  // 1/3 rounded up, to the last bit
  }
  EXPECT_TRUE(jx["slices"][1].is_null());
  const auto& ju = j["variables"]["u"]["components"][0]["gates"][0];
  EXPECT_TRUE(ju[0].is_null() && ju[1].is_null());
  EXPECT_EQ(j["variables"]["a"]["kind"], "interval");
  EXPECT_EQ(j["variables"]["a"]["value"][0][0].get<double>(), 1.5);
  EXPECT_EQ(j["variables"]["b"]["dim"], 2);
  EXPECT_EQ(j["variables"]["b"]["value"][1][1].get<double>(), 3.0);
  EXPECT_EQ(j["status"], "solved");
}

// --out at the problem's own folder, where a table is named like a tube
// (x.csv): refused before anything is written, naming both; the table intact.
TEST(WriteResults, NeverOverwritesAnInput) {
  const auto dir = std::filesystem::temp_directory_path() / ("sillage_out_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "x.csv") << "t,x\n0,1\n1,2\n";
  const std::string text = "[time]\ndomain = [0, 1]\ndelta = 0.5\n[data.logged]\nfile = \"x.csv\"\n"
                           "[var.x]\nkind = \"tube\"\n[[constraint]]\nkind = \"expr\"\nexpr = \"x - 1\"\n";
  std::ofstream(dir / "p.toml") << text;
  const Problem p = load_problem((dir / "p.toml").string());
  const SolveResult r = solve_problem(p);
  std::string msg;
  try {
    write_results(p, r, dir.string());
  } catch (const Error& e) {
    msg = e.what();
  }
  EXPECT_NE(msg.find("the output " + (dir / "x.csv").string() + " would overwrite the table 'logged' (" + (dir / "p.toml").string() +
                     ":4:7), " + (dir / "x.csv").string() + ": choose another output directory (--out)"),
            std::string::npos)
      << msg;
  EXPECT_EQ(problem_test::read_file((dir / "x.csv").string()), "t,x\n0,1\n1,2\n");
  EXPECT_FALSE(std::filesystem::exists(dir / "results.json"));
  EXPECT_NO_THROW(check_output_dir(p, (dir / "out").string(), true));
  std::filesystem::remove_all(dir);
}

// Outputs in proportion: past max_slices, every g-th time point with the hull
// of the slices and gates between (an enclosure still), an empty group empty;
// max_slices = 0 writes every slice.
TEST(WriteResults, DecimatedOutputsStillEnclose) {
  const Problem p = problem_test::parse("[time]\ndomain = [0, 25]\ndelta = 1\n"
                                        "[var.x]\nkind = \"tube\"\nvalue = \"sin(t) + [-0.1, 0.1]\"\n"
                                        "[[constraint]]\nkind = \"expr\"\nexpr = \"x - x\"\n");
  SolveResult r = solve_problem(p);
  ASSERT_FALSE(r.empty) << r.why_empty;
  Tube& x = (*r.built.var("x").tubes)[0];
  x.set(Interval::empty(), 7);  // as a writer may meet it
  const OutputOptions o{10};
  EXPECT_EQ(decimation(25, o), 3u);
  EXPECT_EQ(decimation(10, o), 1u);
  EXPECT_EQ(decimation(25, OutputOptions{0}), 1u);
  const auto j = nlohmann::json::parse(results_json(p, r, o));
  EXPECT_EQ(j["decimated"], 3);
  const auto& times = j["times"];
  ASSERT_EQ(times.size(), 10u);  // 0, 3, ..., 24, and 25
  EXPECT_EQ(times[9], 25.0);
  const auto& gates = j["variables"]["x"]["components"][0]["gates"];
  const auto& slices = j["variables"]["x"]["components"][0]["slices"];
  ASSERT_EQ(gates.size(), 10u);
  ASSERT_EQ(slices.size(), 9u);
  for (std::size_t q = 0; q < 9; ++q) {
    const std::size_t a = 3 * q, b = std::min<std::size_t>(a + 3, 25);
    EXPECT_EQ(gates[q][0].get<double>(), x.gate(a).lb());
    if (a <= 7 && 7 < b) {  // the group with the empty slice
      EXPECT_TRUE(slices[q].is_null());
      continue;
    }
    Interval hull = Interval::empty();  // the slices a..b-1 and the gates a+1..b-1
    for (std::size_t k = a; k < b; ++k) hull |= k > a ? x.slice(k) | x.gate(k) : x.slice(k);
    EXPECT_EQ(slices[q][0].get<double>(), hull.lb());
    EXPECT_EQ(slices[q][1].get<double>(), hull.ub());
  }
  const std::string csv = tube_csv(r.built.var("x"), o);
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 1 + 10 + 9);  // header, gates, slices
  const std::string full = tube_csv(r.built.var("x"), OutputOptions{0});
  EXPECT_EQ(std::count(full.begin(), full.end(), '\n'), 1 + 26 + 25);
  EXPECT_EQ(nlohmann::json::parse(results_json(p, r))["decimated"], 1);  // 25 slices: whole by default
}
