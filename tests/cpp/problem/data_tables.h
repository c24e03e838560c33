#pragma once
// Small data tables for the problem tests, written once per process in a
// temporary folder: 4 stamps, 3 odometry periods, 2 beacons, 3 ranges; and
// the same tables as a robot's logs, with text columns added.
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace problem_test {

inline std::string data_dir() {
  static const std::string dir = [] {
    const auto d = std::filesystem::temp_directory_path() / ("sillage_problem_tables_" + std::to_string(::getpid()));
    std::filesystem::create_directories(d);
    std::ofstream(d / "stamps.csv") << "t\n0\n0.5\n1.5\n2\n";
    std::ofstream(d / "odo.csv") << "d,h\n0.5,0.1\n1,0.2\n0.5,0.3\n";
    std::ofstream(d / "beacons.csv") << "id,bx,by\n3,10,0\n7,0,10\n";
    std::ofstream(d / "ranges.csv") << "t,id,r\n1,3,9\n1.6,7,9\n1.8,9,1\n";
    std::ofstream(d / "stamps_log.csv") << "t,label\n0,start\n0.5,a\n1.5,b\n2,stop\n";
    std::ofstream(d / "odo_log.csv") << "d,frame,h\n0.5,base_link,0.1\n1,base_link,0.2\n0.5,odom,0.3\n";
    std::ofstream(d / "beacons_log.csv") << "id,name,bx,by\n3,north gate,10,0\n7,east gate,0,10\n";
    std::ofstream(d / "ranges_log.csv") << "t,id,r,status\n1,3,9,ok\n1.6,7,9,\n1.8,9,1,multipath\n";
    return d.string();
  }();
  return dir;
}

// The [data.NAME] table of one of those files.
inline std::string table(const std::string& name, const std::string& file) {
  return "[data." + name + "]\nfile = \"" + data_dir() + "/" + file + "\"\n";
}

}  // namespace problem_test
