// CsvTable: numeric CSV files of the datasets; columns as numpy arrays.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <span>
#include <string>
#include <vector>

#include "bindings.h"
#include "docstrings.h"
#include "sillage/error.h"
#include "sillage/io/csv.h"

namespace sillage::python {

namespace {

// Row i of t (signed: a negative i is an OutOfRangeError naming `what`, not a cast error).
std::size_t row_index(const CsvTable& t, py::ssize_t i, const char* what) {
  if (i < 0) throw OutOfRangeError(std::string(what) + ": no row " + std::to_string(i) + " (" + t.rows_text() + ")");
  return static_cast<std::size_t>(i);
}

}  // namespace

SILLAGE_BINDING(io) {
  py::class_<CsvTable>(m, "CsvTable",
                       DOC(CsvTable))
      .def("__repr__",
           [](const CsvTable& t) {
             std::string s = "CsvTable(" + std::to_string(t.nb_rows()) + " rows, columns=[";
             for (std::size_t i = 0; i < t.columns().size(); ++i) s += (i ? ", '" : "'") + t.columns()[i] + "'";
             return s + "])";
           })
      .SILLAGE_DEF_STATIC(CsvTable, read, py::arg("path"))
      .SILLAGE_DEF_STATIC(CsvTable, parse, py::arg("text"), py::arg("source") = "<text>")
      .SILLAGE_DEFS(CsvTable, columns, nb_rows)
      .def(
          "row",
          [](const CsvTable& t, py::ssize_t i) {
            const std::span<const double> r = t.row(row_index(t, i, "CsvTable.row"));
            return std::vector<double>(r.begin(), r.end());
          },
          py::arg("i"),
          "Row i as a list of floats (OutOfRangeError if i < 0 or i >= nb_rows()); a cell that is not a number "
          "is nan: read only the columns that column() or is_numeric() accepts.")
      .SILLAGE_DEF(CsvTable, source)
      .def(
          "line",
          [](const CsvTable& t, py::ssize_t i) { return t.line(row_index(t, i, "CsvTable.line")); },
          py::arg("i"), DOC(CsvTable, line))
      .def(
          "where",
          [](const CsvTable& t, py::ssize_t i) { return t.where(row_index(t, i, "CsvTable.where")); },
          py::arg("i"), DOC(CsvTable, where))
      .SILLAGE_DEF(CsvTable, has_column, py::arg("name"))
      .SILLAGE_DEF(CsvTable, column, py::arg("name"))
      .SILLAGE_DEF(CsvTable, is_numeric, py::arg("name"))
      .SILLAGE_DEF(CsvTable, check_numeric, py::arg("c"))
      .def(
          "values",
          [](const CsvTable& t, const std::string& name) {
            const std::vector<double> v = t.values(name);
            return py::array_t<double>(static_cast<py::ssize_t>(v.size()), v.data());
          },
          py::arg("name"), DOC(CsvTable, values));
}

}  // namespace sillage::python
