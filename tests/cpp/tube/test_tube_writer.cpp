// Tube::Writer, the scoped write access to a tube's slices and gates: the
// version steps once per writer, when it ends; the spans have the tube's
// sizes; commit(false) leaves the version (and the caches) as they were.
#include <gtest/gtest.h>

#include <utility>

#include "sillage/tube/synthesis_tree.h"
#include "sillage/tube/tube.h"

using namespace sillage;

TEST(TubeWriter, VersionStepsOncePerWriter) {
  Tube x(TDomain::create(0.0, 1.0, 0.1), Interval(-1, 1));
  const auto v0 = x.version();
  {
    const Tube::Writer w = x.write();
    EXPECT_EQ(w.slices().size(), x.nb_slices());
    EXPECT_EQ(w.gates().size(), x.nb_slices() + 1);
    for (Interval& s : w.slices()) s &= Interval(0, 1);
    for (Interval& g : w.gates()) g &= Interval(0, 1);
    w.atom(1) = Interval(0.5);  // slice 0
    EXPECT_EQ(x.version(), v0);  // not before it ends
  }
  EXPECT_EQ(x.version(), v0 + 1);
  EXPECT_EQ(x.slice(0), Interval(0.5));
  EXPECT_EQ(x.slice(1), Interval(0, 1));
  EXPECT_EQ(x.gate(10), Interval(0, 1));
  EXPECT_EQ(x.nb_slices(), 10u);
}

TEST(TubeWriter, CommitOnceThenNothing) {
  Tube x(TDomain::create(0.0, 1.0, 0.25), Interval(-1, 1));
  const auto v0 = x.version();
  Tube::Writer w = x.write();
  w.gates()[0] = Interval(0);
  w.commit();
  w.commit();
  EXPECT_EQ(x.version(), v0 + 1);
  {
    Tube::Writer moved = std::move(w);  // a finished writer moved: still finished
  }
  EXPECT_EQ(x.version(), v0 + 1);
  {
    Tube::Writer a = x.write();
    Tube::Writer b = std::move(a);  // one write, whoever ends it
  }
  EXPECT_EQ(x.version(), v0 + 2);
}

TEST(TubeWriter, UnchangedKeepsTheCaches) {
  Tube x(TDomain::create(0.0, 1.0, 0.01), Interval(-1, 1));
  const auto tree = x.synthesis_tree();
  const auto v0 = x.version();
  x.write().commit(false);  // looked, changed nothing
  EXPECT_EQ(x.version(), v0);
  EXPECT_EQ(x.synthesis_tree(), tree);
  {
    const Tube::Writer w = x.write();
    w.slices()[50] = Interval(5);  // a value no old cache holds
  }
  EXPECT_NE(x.synthesis_tree(), tree);  // rebuilt on the new values
  EXPECT_EQ(x(Interval(0.0, 1.0)), Interval(-1, 5));
}
