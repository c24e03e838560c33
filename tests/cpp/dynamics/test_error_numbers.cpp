// A number in a message is written in 17 significant digits at most, never
// as std::to_string writes 1e308 (309 digits): the bad value is read at a glance.
#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "sillage/ctc/shrink.h"
#include "sillage/dynamics/ctc_biased_increment.h"
#include "sillage/dynamics/ctc_heading.h"
#include "sillage/dynamics/ctc_heading_window.h"
#include "sillage/error.h"

using namespace sillage;

namespace {

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(ErrorNumbers, HugeValuesAreWrittenShort) {
  const std::vector<std::string> messages{
      message_of([] { CtcHeadingWindow(-1e308); }), message_of([] { CtcHeadingWindow(40, -1e308); }),
      message_of([] { CtcHeadingWindow(40, 0, -1e308); }), message_of([] { CtcHeading(-1e308); }),
      message_of([] { CtcBiasedIncrement(-1e308); }), message_of([] { check_ratio(1e308, "ratio"); })};
  for (const std::string& m : messages) {
    EXPECT_NE(m.find("e+308"), std::string::npos) << m;
    EXPECT_LT(m.size(), 120u) << m;
  }
}
