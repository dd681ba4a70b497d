// Stability suite of the refraction pass (../shared/DESIGN.md section 6): one case per stiff or
// extreme input. Each case renders through the pass with the debug output on and asserts
//  - no NaN/Inf in the float colour and the debug arrays (P2, T2, Thickness, Flags),
//  - no OpenGL error left by the pass, and no VTK error message,
//  - an error against a closed form below a stated bound,
//  - continuity: a relative perturbation of 1e-6 of the input (the IOR, or the geometry scaled
//    about its centre) changes T2 and the colour by less than a stated bound.
// Usage: TestStability CASE ROWDIR  (writes ROWDIR/CASE.row)
//        TestStability --table ROWDIR OUT.md  (prints the table of all rows, writes it as markdown)
//        TestStability --clean ROWDIR
// The cases are in rfStabilityCases*.cxx (declared from rfStabilityCases.def in
// rfStabilityCases.h), what they share in rfStabilityScene; this file runs them.
#include "rfStabilityCases.h"

#include "rfStability.h"

#include <vtksys/Directory.hxx>
#include <vtksys/SystemTools.hxx>

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <set>
#include <sstream>


using namespace rftest;
using namespace rfstab;

namespace
{
//------------------------------------------------------------------------------
// The table of cases (rfStabilityCases.def, which CMake reads too: a case listed there is a
// test named stability.<name>).
struct Case
{
  const char* Name;
  Row (*Function)(const char* name);
};

const std::vector<Case>& Cases()
{
  static const std::vector<Case> cases = {
#define RF_STABILITY_CASE(name, function) { name, function },
#include "rfStabilityCases.def"
#undef RF_STABILITY_CASE
  };
  return cases;
}

std::string Format(double v)
{
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.3g", v);
  return buffer;
}

const char* const kHeader = "| case | error measure | max error | bound | NaN/Inf | GL errors | "
                            "perturbation | max dT2 (deg) | bound | max dColour | bound | "
                            "flag changes | result |";
const char* const kRule = "|---|---|---|---|---|---|---|---|---|---|---|---|---|";

std::string TableLine(const Row& r)
{
  std::ostringstream s;
  s << "| " << r.Case << " | " << r.Measure << " | " << Format(r.Error) << " | "
    << Format(r.ErrorBound) << " | " << r.NonFinite << " | " << r.GLErrors << " | "
    << r.Perturbation << " | " << Format(r.DeltaT2) << " | " << Format(r.DeltaT2Bound) << " | "
    << Format(r.DeltaColour) << " | " << Format(r.DeltaColourBound) << " | " << r.FlagChanges
    << " (<= " << r.FlagChangeBound << ") | " << (r.Passed() ? "pass" : "FAIL") << " |";
  return s.str();
}

// A case's row: its table line, written when the case has run (pass or FAIL).
bool WriteRow(const Row& r, const std::string& dir)
{
  std::ofstream out(dir + "/" + r.Case + ".row");
  out << TableLine(r) << "\n";
  out.close();
  if (!out)
  {
    std::fprintf(stderr, "cannot write the row of %s into %s\n", r.Case.c_str(), dir.c_str());
    return false;
  }
  return true;
}

// The fixture's set-up: an empty row folder, so that the table sees only this run's rows.
int Clean(const std::string& dir)
{
  if (vtksys::SystemTools::FileExists(dir))
  {
    const vtksys::Status removed = vtksys::SystemTools::RemoveADirectory(dir);
    if (!removed)
    {
      std::fprintf(stderr, "cannot remove the old rows in %s: %s\n", dir.c_str(),
        removed.GetString().c_str());
      return EXIT_FAILURE;
    }
  }
  const vtksys::Status made = vtksys::SystemTools::MakeDirectory(dir);
  vtksys::Directory folder;
  if (!made || !folder.Load(dir) || folder.GetNumberOfFiles() != 2) // "." and ".."
  {
    std::fprintf(stderr, "cannot make an empty row folder %s: %s\n", dir.c_str(),
      made ? "it is not empty" : made.GetString().c_str());
    return EXIT_FAILURE;
  }
  std::printf("row folder %s is empty\n", dir.c_str());
  return EXIT_SUCCESS;
}

// The table of this run: one row per case of the table of cases. It fails when a case has
// no row (not run, or stopped before writing it: a crash or a time-out), when a row is
// FAIL, or when the folder holds a row of no known case.
int Table(const std::string& dir, const std::string& markdown)
{
  std::ostringstream table;
  table << kHeader << "\n" << kRule << "\n";
  std::vector<std::string> missing;
  std::vector<std::string> failed;
  std::set<std::string> known;
  for (const auto& c : Cases())
  {
    known.insert(std::string(c.Name) + ".row");
    std::ifstream in(dir + "/" + c.Name + ".row");
    std::string line;
    if (!in || !std::getline(in, line))
    {
      table << "| " << c.Name << " | (not run) | | | | | | | | | | | |\n";
      missing.push_back(c.Name);
      continue;
    }
    const std::string passed = "| pass |";
    if (line.size() < passed.size() || line.compare(line.size() - passed.size(), passed.size(), passed) != 0)
    {
      failed.push_back(c.Name);
    }
    table << line << "\n";
  }
  std::vector<std::string> unknown;
  vtksys::Directory folder;
  if (folder.Load(dir))
  {
    for (unsigned long i = 0; i < folder.GetNumberOfFiles(); ++i)
    {
      const std::string file = folder.GetFile(i);
      if (file != "." && file != ".." && !known.count(file))
      {
        unknown.push_back(file);
      }
    }
  }
  std::printf("Stability table (%s):\n%s", markdown.c_str(), table.str().c_str());
  std::ofstream out(markdown);
  out << "# Stability suite: measured figures\n\n"
      << "Written by `ctest -L stability` (TestStability --table). Errors are against closed "
         "forms; dT2 and dColour are the largest changes under a relative perturbation of 1e-6 "
         "of the input, over pixels whose flag did not change.\n\n"
      << table.str();
  out.close();
  auto list = [](const std::vector<std::string>& names) {
    std::string joined;
    for (const auto& n : names)
    {
      joined += (joined.empty() ? "" : ", ") + n;
    }
    return joined;
  };
  std::printf("%zu case(s): %zu failed, %zu without a row\n", Cases().size(), failed.size(),
    missing.size());
  bool ok = true;
  if (!missing.empty())
  {
    std::printf("FAILED: no row (not run, or stopped before its end): %s\n", list(missing).c_str());
    ok = false;
  }
  if (!failed.empty())
  {
    std::printf("FAILED: case(s) failed: %s\n", list(failed).c_str());
    ok = false;
  }
  if (!unknown.empty())
  {
    std::printf("FAILED: rows of no known case in %s: %s\n", dir.c_str(), list(unknown).c_str());
    ok = false;
  }
  if (!out)
  {
    std::printf("FAILED: cannot write %s\n", markdown.c_str());
    ok = false;
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
}

int main(int argc, char* argv[])
{
  if (argc >= 3 && std::strcmp(argv[1], "--clean") == 0)
  {
    return Clean(argv[2]);
  }
  if (argc >= 4 && std::strcmp(argv[1], "--table") == 0)
  {
    return Table(argv[2], argv[3]);
  }
  if (argc < 2)
  {
    std::fprintf(stderr, "usage: %s CASE [ROWDIR] | --table ROWDIR OUT.md | --clean ROWDIR\n",
      argv[0]);
    return EXIT_FAILURE;
  }
  MessageLog* log = InstallLog();
  for (const auto& c : Cases())
  {
    if (c.Name != std::string(argv[1]))
    {
      continue;
    }
    Row row = c.Function(c.Name);
    row.Judge();
    const int errors = log->Count("error");
    row.Require(errors == 0, "VTK reported errors");
    std::printf("%s\n%s\n%s\n", kHeader, kRule, TableLine(row).c_str());
    for (const auto& f : row.Failures)
    {
      std::printf("FAILED %s: %s\n", row.Case.c_str(), f.c_str());
    }
    if (argc >= 3 && !WriteRow(row, argv[2]))
    {
      return EXIT_FAILURE;
    }
    return row.Passed() ? EXIT_SUCCESS : EXIT_FAILURE;
  }
  std::fprintf(stderr, "unknown case %s\n", argv[1]);
  return EXIT_FAILURE;
}
