// Writes the velocity tables of examples/problems/loops_survey.toml
// (loops_survey_velocity.h) into DIR; the build runs it into build/examples/problems.
//
//   loops_survey_velocity DIR
#include <cstdio>

#include "loops_survey_velocity.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: loops_survey_velocity DIR\n");
    return 2;
  }
  if (!loops_survey::write_velocity_csv(looping_mission::Mission{looping_mission::Parameters{}}, argv[1])) {
    std::fprintf(stderr, "loops_survey_velocity: cannot write %s\n", argv[1]);
    return 2;
  }
  return 0;
}
