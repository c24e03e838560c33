// Python bindings of the synthetic bathymetric mission (slam/bathymetry_*.h):
// seabed DEM, mission, sensors and bounds, tide model, tube builders, figures.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bindings.h"
#include "sillage/slam/bathymetry_dem.h"
#include "sillage/slam/bathymetry_figures.h"
#include "sillage/slam/bathymetry_mission.h"
#include "sillage/slam/bathymetry_range_observation.h"
#include "sillage/slam/bathymetry_seabed.h"
#include "sillage/slam/bathymetry_sensors.h"
#include "sillage/slam/bathymetry_tide.h"
#include "sillage/slam/bathymetry_tubes.h"

namespace sillage::python {

namespace {

py::array_t<double> array_of(const std::vector<double>& v) { return py::array_t<double>(v.size(), v.data()); }

using Mission = BathymetryMission;
using MissionPtr = std::shared_ptr<Mission>;

void init_bathymetry_data(py::module_& m) {
  py::class_<SeabedOptions>(m, "SeabedOptions", "Options of generate_seabed (area, grid, depth, smooth strip, counts).")
      .def(py::init<>(), "Defaults: 500 m square, 1 m cells, 21 m base depth, 170 m smooth strip, 7 rocks, 2 banks.")
      .def("__repr__", &fields_repr, "Name(field=value, ...) of every field.")
      .def_readwrite("size", &SeabedOptions::size, "Side of the square area (m), from (0, 0).")
      .def_readwrite("cell", &SeabedOptions::cell, "Grid step (m); an integer or dyadic fraction.")
      .def_readwrite("base_depth", &SeabedOptions::base_depth, "Depth at the origin (m, below the chart datum).")
      .def_readwrite("smooth_width", &SeabedOptions::smooth_width, "Width of the smooth western strip (m).")
      .def_readwrite("nb_rocks", &SeabedOptions::nb_rocks, "Number of rocks.")
      .def_readwrite("nb_banks", &SeabedOptions::nb_banks, "Number of sandbanks.")
      .def_readwrite("relief", &SeabedOptions::relief, "Factor on every relief amplitude (slope, banks, rocks, waves).");
  py::class_<SeabedClass>(m, "SeabedClass",
                          "Stated bounds of a generated seabed: curvature (Hessian norm), slope, node roughness.")
      .def(py::init<double, double, double>(), py::arg("curvature"), py::arg("slope"), py::arg("roughness"),
           "The three bounds.")
      .def("__repr__", [](const SeabedClass& c) { return repr(c); }, "SeabedClass(curvature, slope, roughness).")
      .def_readwrite("curvature", &SeabedClass::curvature, "Bound on the Hessian norm of the smooth seabed (1/m).")
      .def_readwrite("slope", &SeabedClass::slope, "Bound on its gradient norm.")
      .def_readwrite("roughness", &SeabedClass::roughness, "Bound on the node roughness (m).");

  py::class_<BathymetryDem, std::shared_ptr<BathymetryDem>>(
      m, "BathymetryDem",
      "A seabed DEM: node depths on a grid, bilinear in between, as an inclusion function (point and box "
      "enclosures, rounding included; the whole real line outside the map).")
      .def(py::init([](double x0, double y0, double h, const py::array_t<double, py::array::c_style |
                                                                              py::array::forcecast>& depths) {
             if (depths.ndim() != 2) throw DimensionError("BathymetryDem: depths must be a 2-D array (ny, nx)");
             const auto ny = static_cast<std::size_t>(depths.shape(0)), nx = static_cast<std::size_t>(depths.shape(1));
             return BathymetryDem(x0, y0, h, nx, ny, std::vector<double>(depths.data(), depths.data() + nx * ny));
           }),
           py::arg("x0"), py::arg("y0"), py::arg("h"), py::arg("depths"),
           "Nodes (x0 + i h, y0 + j h) with depth depths[j, i] (metres, positive down).")
      .def("__repr__", [](const BathymetryDem& d) { return repr(d); }, "A one-line summary.")
      .def_property_readonly("nx", &BathymetryDem::nx, "Number of node columns.")
      .def_property_readonly("ny", &BathymetryDem::ny, "Number of node rows.")
      .def_property_readonly("cell_size", &BathymetryDem::cell_size, "Grid step (m).")
      .def_property_readonly("x0", &BathymetryDem::x0, "x of node column 0.")
      .def_property_readonly("y0", &BathymetryDem::y0, "y of node row 0.")
      .def("domain", &BathymetryDem::domain, "The box covered by the grid.")
      .def("node", &BathymetryDem::node, py::arg("i"), py::arg("j"), "Depth of node (i, j).")
      .def(
          "depths",
          [](const BathymetryDem& d) {
            py::array_t<double> a({d.ny(), d.nx()});
            std::copy(d.depths().begin(), d.depths().end(), a.mutable_data());
            return a;
          },
          "The node depths as an (ny, nx) array.")
      .def("min_depth", &BathymetryDem::min_depth, "Smallest node depth.")
      .def("max_depth", &BathymetryDem::max_depth, "Largest node depth.")
      .def("__call__", &BathymetryDem::operator(), py::arg("x"), py::arg("y"),
           "The bilinear depth at (x, y), an enclosing Interval.")
      .def("eval", &BathymetryDem::eval, py::arg("box"),
           "The exact range of the bilinear seabed over a box (x, y), outward-rounded.")
      .def("eval_cells", &BathymetryDem::eval_cells, py::arg("box"),
           "The hull of the nodes of every cell the box touches (looser, cheaper).");

  py::class_<Seabed>(m, "Seabed", "A generated seabed: its DEM, its stated class and its smooth strip.")
      .def("__repr__", [](const Seabed& s) { return "Seabed(" + repr(s.dem) + ", " + repr(s.bounds) + ")"; },
           "A one-line summary.")
      .def_readonly("dem", &Seabed::dem, "The BathymetryDem.")
      .def_readonly("bounds", &Seabed::bounds, "The SeabedClass.")
      .def_readonly("smooth_region", &Seabed::smooth_region, "The low-information strip, a box.");
  m.def(
      "generate_seabed",
      [](std::uint64_t seed, const SeabedOptions& o) {
        py::gil_scoped_release unlocked;
        return generate_seabed(seed, o);
      },
      py::arg("seed"), py::arg("options") = SeabedOptions{},
      "A synthetic seabed (slope, banks, sand waves, rocks, a smooth strip), deterministic from the seed.");

  py::class_<TideModel>(m, "TideModel", "The sinusoidal tide model (7.29): ma sin^2((pi/2)(t - t_low)/Du).")
      .def(py::init([](double range, double duration, double t_low, const Interval& error) {
             return TideModel{range, duration, t_low, error};
           }),
           py::arg("range") = 5.2, py::arg("duration") = 22320.0, py::arg("t_low") = -5400.0,
           py::arg("error") = Interval(0.0),
           "Defaults: range 5.2 m, duration 22320 s, low water 5400 s before the start, no model error.")
      .def("__repr__", [](const TideModel& t) { return repr(t); }, "TideModel(range, duration, t_low).")
      .def_readwrite("range", &TideModel::range, "Tidal range ma (m).")
      .def_readwrite("duration", &TideModel::duration, "Duration of the rising tide Du (s).")
      .def_readwrite("t_low", &TideModel::t_low, "Time of low water (mission seconds).")
      .def_readwrite("error", &TideModel::error, "The bounded error of the model (m), contains 0.")
      .def("__call__", &TideModel::operator(), py::arg("t"), "height(t) + error: the tide over [t], rigorous.")
      .def("height", &TideModel::height, py::arg("t"), "The sea height above datum over [t], an enclosing Interval.")
      .def("height_value", &TideModel::height_value, py::arg("t"), "The model's height at t, a float.");

  py::class_<BathymetrySensorBounds>(m, "BathymetrySensorBounds",
                                     "The stated sensor bounds (datasheet class, with margins) and dynamics class.")
      .def(py::init<>(), "Defaults: DVL +-(0.2 % + 1 mm/s), INS +-0.05 deg, depth +-0.05 m, altitude +-(1 % + 5 cm), "
                         "tide +-0.1 m.")
      .def("__repr__", [](const BathymetrySensorBounds& b) { return repr(b); }, "A one-line summary.")
      .def_readwrite("dvl_scale", &BathymetrySensorBounds::dvl_scale, "DVL relative error, of the measured speed.")
      .def_readwrite("dvl_offset", &BathymetrySensorBounds::dvl_offset, "DVL offset error (m/s).")
      .def_readwrite("heading", &BathymetrySensorBounds::heading, "INS heading error (deg).")
      .def_readwrite("attitude", &BathymetrySensorBounds::attitude, "INS pitch and roll error (deg).")
      .def_readwrite("depth", &BathymetrySensorBounds::depth, "Pressure depth error (m).")
      .def_readwrite("altitude_scale", &BathymetrySensorBounds::altitude_scale, "DVL altitude relative error.")
      .def_readwrite("altitude_offset", &BathymetrySensorBounds::altitude_offset, "DVL altitude offset error (m).")
      .def_readwrite("tide", &BathymetrySensorBounds::tide, "Tide model error (m).")
      .def_readwrite("angle_accel", &BathymetrySensorBounds::angle_accel, "Angular acceleration bound (deg/s^2).")
      .def_readwrite("velocity_accel2", &BathymetrySensorBounds::velocity_accel2,
                     "Bound on the second derivative of the body velocity (m/s^3).")
      .def_readwrite("speed_max", &BathymetrySensorBounds::speed_max, "Horizontal speed bound (m/s).")
      .def_readwrite("beam_angle", &BathymetrySensorBounds::beam_angle, "DVL beam angle off-nadir (deg).")
      .def_readwrite("beam_spread", &BathymetrySensorBounds::beam_spread, "Lobe half-width off-nadir (deg).")
      .def_readwrite("beam_azimuth_spread", &BathymetrySensorBounds::beam_azimuth_spread,
                     "Lobe half-width in azimuth (deg).");
  m.def("dvl_footprint", &dvl_footprint, py::arg("x"), py::arg("y"), py::arg("yaw"), py::arg("altitude"),
        py::arg("bounds") = BathymetrySensorBounds{}, "The 20 seabed points seen by the 4 DVL beams (Fig. 7.11).");
  m.def("footprint_depth", &footprint_depth, py::arg("dem"), py::arg("x"), py::arg("y"), py::arg("yaw"),
        py::arg("altitude"), py::arg("bounds") = BathymetrySensorBounds{},
        "The seabed depth filtered over the DVL footprint (mean over dvl_footprint).");
  m.def("footprint_filter_bound", &footprint_filter_bound, py::arg("seabed"), py::arg("cell"), py::arg("altitude_max"),
        py::arg("bounds") = BathymetrySensorBounds{},
        "Bound on |footprint_depth - nadir depth| for a nadir altitude <= altitude_max.");
  m.def("nadir_altitude_max", &nadir_altitude_max, py::arg("measured"), py::arg("seabed"), py::arg("cell"),
        py::arg("bounds") = BathymetrySensorBounds{}, "An upper bound of the nadir altitude from a measured one.");
}

void init_bathymetry_mission(py::module_& m) {
  py::class_<BathymetryMissionOptions>(m, "BathymetryMissionOptions", "Options of BathymetryMission.")
      .def(py::init<>(), "Defaults: 5760 s at 0.1 s, 1.03 m/s, 28 m turns, 40 m rails, 14.5 m depth.")
      .def("__repr__", &fields_repr, "Name(field=value, ...) of every field.")
      .def_readwrite("duration", &BathymetryMissionOptions::duration, "Mission duration (s).")
      .def_readwrite("step", &BathymetryMissionOptions::step, "Sensor period (s).")
      .def_readwrite("speed", &BathymetryMissionOptions::speed, "Nominal speed (m/s).")
      .def_readwrite("turn_radius", &BathymetryMissionOptions::turn_radius, "Turning radius (m).")
      .def_readwrite("rail_spacing", &BathymetryMissionOptions::rail_spacing,
                     "Distance between rails (m), < 2 turn_radius.")
      .def_readwrite("depth", &BathymetryMissionOptions::depth, "Depth at the start (m).")
      .def_readwrite("seabed", &BathymetryMissionOptions::seabed, "The SeabedOptions.")
      .def_readwrite("tide", &BathymetryMissionOptions::tide, "The TideModel.")
      .def_readwrite("bounds", &BathymetryMissionOptions::bounds, "The BathymetrySensorBounds.");

  py::class_<BathymetrySignals>(m, "BathymetrySignals",
                                "Signals at the sample times (numpy arrays): yaw, pitch, roll (rad), vx, vy, vz "
                                "(body, m/s), depth, altitude (m).")
      .def("__repr__", [](const BathymetrySignals& s) { return "BathymetrySignals(" + std::to_string(s.yaw.size()) +
                                                               " samples)"; },
           "BathymetrySignals(n samples).")
#define SILLAGE_SIGNAL(name, doc) \
  .def_property_readonly(#name, [](const BathymetrySignals& s) { return array_of(s.name); }, doc)
      SILLAGE_SIGNAL(yaw, "Yaw, counter-clockwise from east (rad).")
      SILLAGE_SIGNAL(pitch, "Pitch, positive nose down (rad).")
      SILLAGE_SIGNAL(roll, "Roll (rad).")
      SILLAGE_SIGNAL(vx, "Body velocity, forward (m/s).")
      SILLAGE_SIGNAL(vy, "Body velocity, left (m/s).")
      SILLAGE_SIGNAL(vz, "Body velocity, up (m/s).")
      SILLAGE_SIGNAL(depth, "Depth below the surface (m).")
      SILLAGE_SIGNAL(altitude, "Altitude (m): nadir (truth) or DVL (measured).");
#undef SILLAGE_SIGNAL

  py::class_<Mission, MissionPtr>(m, "BathymetryMission",
                                  "A synthetic AUV bathymetric survey (thesis 7.3.2), deterministic from a seed: "
                                  "seabed, truth, measurements within stated bounds.")
      .def(py::init([](std::uint64_t seed, const std::optional<BathymetryMissionOptions>& o) {
             py::gil_scoped_release unlocked;
             return std::make_shared<Mission>(seed, o ? *o : BathymetryMissionOptions{});
           }),
           py::arg("seed") = 7, py::arg("options") = py::none(), "Generates the mission (about 0.4 s).")
      .def("__repr__", [](const Mission& x) { return repr(x); }, "A one-line summary.")
      .def_property_readonly("seed", &Mission::seed, "The seed.")
      .def_property_readonly("options", &Mission::options, "The BathymetryMissionOptions.")
      .def_property_readonly("seabed", &Mission::seabed, "The Seabed.")
      .def_property_readonly("dem", &Mission::dem, "The BathymetryDem of the seabed.")
      .def_property_readonly("bounds", &Mission::bounds, "The BathymetrySensorBounds.")
      .def_property_readonly("tide", &Mission::tide, "The TideModel.")
      .def_property_readonly("nb_samples", &Mission::nb_samples, "Number of samples.")
      .def_property_readonly("times", [](const Mission& x) { return array_of(x.times()); }, "Sample times (s).")
      .def_property_readonly("x1", [](const Mission& x) { return array_of(x.x1()); }, "True east position (m).")
      .def_property_readonly("x2", [](const Mission& x) { return array_of(x.x2()); }, "True north position (m).")
      .def_property_readonly("truth", &Mission::truth, "The true BathymetrySignals.")
      .def_property_readonly("measured", &Mission::measured, "The measured BathymetrySignals.")
      .def_property_readonly("tide_truth", [](const Mission& x) { return array_of(x.tide_truth()); },
                             "The true sea height above datum (m).")
      .def_property_readonly("filtered_altitude", [](const Mission& x) { return array_of(x.filtered_altitude()); },
                             "The footprint-filtered altitude before noise (m).")
      .def("path_length", &Mission::path_length, "Horizontal path length (m).")
      .def("tdomain", &Mission::tdomain, py::arg("dt"),
           "A TDomain of every (dt / step)-th sample time: the domain the tube builders accept.")
      .def("sample_index", &Mission::sample_index, py::arg("t"), "Index of the sample at time t, or -1.");

  auto released = py::call_guard<py::gil_scoped_release>();
  m.def("bathymetry_sensor_tubes", &bathymetry_sensor_tubes, py::arg("mission"), py::arg("tdomain"), released,
        "The tubes (psi, theta, phi, vx, vy, vz) from the measurements and bounds.");
  m.def("bathymetry_velocity_tube", &bathymetry_velocity_tube, py::arg("mission"), py::arg("tdomain"), released,
        "w = R(psi, theta, phi) v_r (7.31): (east, north, depth) velocity tube.");
  m.def("bathymetry_dead_reckoning", &bathymetry_dead_reckoning, py::arg("mission"), py::arg("tdomain"),
        py::arg("x0"), released, "The dead-reckoning tube p (east, north, depth) from the start box x0.");
  m.def("bathymetry_initial_box", &bathymetry_initial_box, py::arg("mission"), py::arg("horizontal") = 1.0,
        "The start box: truth +- horizontal (m) east and north, the measured depth +- its bound.");
  m.def("bathymetry_observation_tube", &bathymetry_observation_tube, py::arg("mission"), py::arg("tdomain"), released,
        "The observation tube z = z_alt + z_depth + z_tide (7.30): the seabed depth under the vehicle.");
  m.def("bathymetry_observation_rate_bound", &bathymetry_observation_rate_bound, py::arg("mission"),
        "The bound on |z'| used between samples (m/s).");
  m.def("bathymetry_truth", &bathymetry_truth, py::arg("mission"), "The true (east, north, depth) TrajectoryVector.");
  m.def("bathymetry_truth_observation", &bathymetry_truth_observation, py::arg("mission"),
        "The true observation (DEM under the true path) as a Trajectory.");

  m.def("depth_colour", &depth_colour, py::arg("depth"), py::arg("lo"), py::arg("hi"),
        "The figure colour of a depth within [lo, hi].");
  m.def("bathymetry_dem_figure", &bathymetry_dem_figure, py::arg("dem"), py::arg("x"), py::arg("y"),
        py::arg("title") = "Seabed DEM and path", py::arg("block") = 5.0, py::arg("width_px") = 600.0,
        "The DEM coloured by depth with the path (x, y) (Fig. 7.20), an SVG Figure.");
  m.def("bathymetry_map_figure", &bathymetry_map_figure, py::arg("mission"), py::arg("p"),
        py::arg("title") = "Mission map: dead reckoning and truth", py::arg("width_px") = 600.0,
        "The mission map: tube [p1] x [p2] and the truth (Fig. 7.16), an SVG Figure.");
  m.def("bathymetry_observation_figure", &bathymetry_observation_figure, py::arg("mission"), py::arg("z"),
        py::arg("title") = "Observation tube [z](t) and truth", py::arg("width_px") = 700.0,
        "The observation tube with the true observation (Fig. 7.14), an SVG Figure.");
}

void init_range_observation(py::module_& m) {
  py::class_<RangeBounds>(m, "RangeBounds",
                          "Stated bounds of range measurements: short and long errors, time stamps, speed.")
      .def(py::init<>(), "Defaults (plaza1): short 1.5 m, long 10 m, time stamps 0.2 s, speed 2 m/s.")
      .def(py::init<double, double, double, double>(), py::arg("short_err"), py::arg("long_err"),
           py::arg("time_err"), py::arg("speed"), "The four bounds.")
      .def("__repr__", [](const RangeBounds& b) { return repr(b); }, "RangeBounds(short_err, long_err, ...).")
      .def_readwrite("short_err", &RangeBounds::short_err, "measured - true >= -short_err (m).")
      .def_readwrite("long_err", &RangeBounds::long_err, "measured - true <= long_err (m).")
      .def_readwrite("time_err", &RangeBounds::time_err, "Time-stamp error (s).")
      .def_readwrite("speed", &RangeBounds::speed, "Bound on |z'|: the robot's speed (m/s).");
  m.def("range_observation_tubes", &range_observation_tubes, py::arg("tdomain"), py::arg("times"),
        py::arg("beacon"), py::arg("range"), py::arg("beacon_ids"), py::arg("bounds") = RangeBounds{},
        py::call_guard<py::gil_scoped_release>(),
        "The range observation tubes of a range-only temporal SLAM without the beacon positions: one tube per "
        "id of beacon_ids, from the measurements (times, beacon, range) and the stated bounds.");
}

}  // namespace

void init_bathymetry(py::module_& m) {
  init_bathymetry_data(m);
  init_bathymetry_mission(m);
  init_range_observation(m);
}

}  // namespace sillage::python
