#include "rfDeclaredSizes.h"

#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <cstring>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <sstream>
#include <vector>

namespace
{
// zlib's largest ratio (deflate: 1032 to 1): an XML file's compressed data expand no further.
constexpr double LargestCompression = 1032.0;

std::string Lower(std::string text)
{
  return vtksys::SystemTools::LowerCase(text);
}

// The file from its start up to and including the first `marker` (the whole file without one),
// at most `limit` bytes.
std::string ReadUntil(std::ifstream& file, const std::string& marker, size_t limit)
{
  std::string text;
  char chunk[65536];
  while (text.size() < limit && file)
  {
    file.read(chunk, static_cast<std::streamsize>(std::min(sizeof(chunk), limit - text.size())));
    const size_t from = text.size() > marker.size() ? text.size() - marker.size() : 0;
    text.append(chunk, static_cast<size_t>(file.gcount()));
    if (!marker.empty() && text.find(marker, from) != std::string::npos)
    {
      break;
    }
  }
  return text;
}

// Every value a file holds takes at least one byte of it (ASCII: a digit; binary: a byte or
// more), so `values` declared items fit only in a file of at least that many bytes.
bool Fits(double values, double bytes, const std::string& what, std::string& error)
{
  if (values >= 0.0 && values <= bytes)
  {
    return true;
  }
  std::ostringstream text;
  text << "it declares " << what << (values < 0.0 ? " (a negative count)" : "") << ", more than its "
       << static_cast<long long>(bytes) << " bytes can hold";
  error = text.str();
  return false;
}

// A count written in the file: a non-negative integer (-1: not one).
double Count(const std::string& token)
{
  if (token.empty() || token.size() > 19 ||
    !std::all_of(token.begin(), token.end(), [](char c) { return c >= '0' && c <= '9'; }))
  {
    return -1.0;
  }
  return std::stod(token);
}

bool CheckLegacy(const std::string& text, double bytes, std::string& error)
{
  // The keywords that size what the reader allocates; a line of binary data that happens to
  // begin like one is read as one (at worst a refusal naming what it declared).
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line))
  {
    std::istringstream words(line);
    std::vector<std::string> w{ std::istream_iterator<std::string>(words),
      std::istream_iterator<std::string>() };
    if (w.size() < 2)
    {
      continue;
    }
    // VTK's legacy readers compare a keyword's first letters only ("POINTS4" is POINTS).
    std::string key = vtksys::SystemTools::UpperCase(w[0]);
    static const char* const keywords[] = { "POINTS", "POLYGONS", "LINES", "VERTICES",
      "TRIANGLE_STRIPS", "CELLS", "CELL_TYPES", "POINT_DATA", "CELL_DATA", "DIMENSIONS" };
    for (const char* keyword : keywords)
    {
      if (key.compare(0, std::strlen(keyword), keyword) == 0)
      {
        key = keyword;
      }
    }
    double values = -2.0;
    if (key == "POINTS")
    {
      values = 3.0 * Count(w[1]);
    }
    else if ((key == "POLYGONS" || key == "LINES" || key == "VERTICES" ||
               key == "TRIANGLE_STRIPS" || key == "CELLS") &&
      w.size() >= 3)
    {
      values = std::max(Count(w[1]), Count(w[2]));
      values = std::min(Count(w[1]), Count(w[2])) < 0.0 ? -1.0 : values;
    }
    else if (key == "CELL_TYPES" || key == "POINT_DATA" || key == "CELL_DATA")
    {
      values = Count(w[1]);
    }
    else if (key == "DIMENSIONS" && w.size() >= 4)
    {
      const double n[3] = { Count(w[1]), Count(w[2]), Count(w[3]) };
      values = *std::min_element(n, n + 3) < 0.0 ? -1.0 : n[0] * n[1] * n[2];
    }
    if (values != -2.0 && !Fits(values, bytes, key + " " + w[1], error))
    {
      return false;
    }
  }
  return true;
}

bool CheckPLY(const std::string& text, double bytes, std::string& error)
{
  static const char* const types[] = { "char", "uchar", "short", "ushort", "int", "uint",
    "float", "double", "int8", "uint8", "int16", "uint16", "int32", "uint32", "float32",
    "float64" };
  auto known = [](const std::string& type) {
    return std::find(std::begin(types), std::end(types), type) != std::end(types);
  };
  std::istringstream lines(text);
  std::string line;
  bool element = false;
  bool format = false;
  int number = 0;
  while (std::getline(lines, line))
  {
    ++number;
    std::istringstream words(line);
    std::vector<std::string> w{ std::istream_iterator<std::string>(words),
      std::istream_iterator<std::string>() };
    const std::string where = "its header, line " + std::to_string(number) + ", ";
    if (number == 1)
    {
      if (w.size() != 1 || w[0] != "ply")
      {
        error = "it does not begin with 'ply'";
        return false;
      }
      continue;
    }
    if (w.empty() || w[0] == "comment" || w[0] == "obj_info")
    {
      continue;
    }
    if (w[0] == "end_header")
    {
      if (!format)
      {
        error = "its header has no 'format' line";
        return false;
      }
      return true;
    }
    if (w[0] == "format")
    {
      if (w.size() != 3 ||
        (w[1] != "ascii" && w[1] != "binary_little_endian" && w[1] != "binary_big_endian"))
      {
        error = where + "names no known format (ascii, binary_little_endian, binary_big_endian)";
        return false;
      }
      format = true;
    }
    else if (w[0] == "element")
    {
      if (w.size() != 3 || !Fits(Count(w[2]), bytes, "element " + w[1] + " " + w[2], error))
      {
        error = error.empty() ? where + "is not 'element NAME COUNT'" : error;
        return false;
      }
      element = true;
    }
    else if (w[0] == "property")
    {
      const bool list = w.size() == 5 && w[1] == "list" && known(w[2]) && known(w[3]);
      if (!element || !(list || (w.size() == 3 && known(w[1]))))
      {
        error = where +
          (element ? "is not 'property TYPE NAME' or 'property list TYPE TYPE NAME' (known "
                     "types: char, uchar, short, ushort, int, uint, float, double and their "
                     "sized names)"
                   : "declares a property before any element");
        return false;
      }
    }
    else
    {
      error = where + "begins with an unknown keyword '" + w[0] + "'";
      return false;
    }
  }
  error = "its header has no 'end_header'";
  return false;
}

// A binary STL (as VTK's reader decides: vtksys's file type detection) declares its
// triangles' count after an 80-byte header; each takes 50 bytes.
bool CheckBinarySTL(
  const std::string& path, const std::string& text, double bytes, std::string& error)
{
  if (vtksys::SystemTools::DetectFileType(path.c_str()) == vtksys::SystemTools::FileTypeText)
  {
    return true;
  }
  if (text.size() < 84)
  {
    error = "it is read as a binary STL, and is shorter than a binary STL's 84-byte header";
    return false;
  }
  const unsigned char* count = reinterpret_cast<const unsigned char*>(text.data()) + 80;
  const double triangles = static_cast<double>(static_cast<uint32_t>(count[0]) |
    static_cast<uint32_t>(count[1]) << 8 | static_cast<uint32_t>(count[2]) << 16 |
    static_cast<uint32_t>(count[3]) << 24);
  return Fits(84.0 + 50.0 * triangles, bytes,
    "a binary STL of " + std::to_string(static_cast<long long>(triangles)) +
      " triangles (50 bytes each)",
    error);
}

bool CheckXML(const std::string& text, double bytes, std::string& error)
{
  const double room = text.find("compressor=") != std::string::npos ? bytes * LargestCompression
                                                                     : bytes;
  static const char* const counts[] = { "NumberOfPoints", "NumberOfCells", "NumberOfVerts",
    "NumberOfLines", "NumberOfStrips", "NumberOfPolys", "NumberOfTuples" };
  for (const char* name : counts)
  {
    const std::string key = std::string(" ") + name + "=\"";
    for (size_t at = text.find(key); at != std::string::npos; at = text.find(key, at + 1))
    {
      const size_t begin = at + key.size();
      const size_t end = text.find('"', begin);
      const std::string value = text.substr(begin, end == std::string::npos ? 0 : end - begin);
      if (!Fits(Count(value), room, std::string(name) + "=" + value, error))
      {
        return false;
      }
    }
  }
  // Structured data: the points an extent spans, when the file holds any array for them.
  if (text.find("<DataArray") == std::string::npos)
  {
    return true;
  }
  for (const char* name : { " WholeExtent=\"", " Extent=\"" })
  {
    const std::string key = name;
    for (size_t at = text.find(key); at != std::string::npos; at = text.find(key, at + 1))
    {
      std::istringstream numbers(text.substr(at + key.size(), 200));
      double points = 1.0;
      for (int k = 0; k < 3; ++k)
      {
        long long lo = 0;
        long long hi = 0;
        if (!(numbers >> lo >> hi))
        {
          break;
        }
        points *= hi >= lo ? static_cast<double>(hi - lo) + 1.0 : 0.0;
      }
      if (!Fits(points, room, "an extent of " + std::to_string(points) + " points", error))
      {
        return false;
      }
    }
  }
  return true;
}
}

bool rfCheckDeclaredSizes(const std::string& path, std::string& error)
{
  const std::string extension =
    Lower(vtksys::SystemTools::GetFilenameLastExtension(path));
  const bool legacy = extension == ".vtk";
  const bool ply = extension == ".ply";
  const bool stl = extension == ".stl";
  const bool xml = extension == ".vtp" || extension == ".vtu" || extension == ".vti" ||
    extension == ".vts" || extension == ".vtr";
  if (!legacy && !ply && !stl && !xml)
  {
    return true;
  }
  std::ifstream file(path, std::ios::binary);
  if (!file)
  {
    error = "it cannot be opened";
    return false;
  }
  // Only as much as declares the sizes: a binary STL's header, a PLY header, an XML file up
  // to its appended data (a large mesh's bulk); a legacy file declares sizes throughout.
  const double bytes = static_cast<double>(vtksys::SystemTools::FileLength(path));
  const std::string text = stl ? ReadUntil(file, "", 84)
    : ply                      ? ReadUntil(file, "end_header", std::string::npos)
    : xml                      ? ReadUntil(file, "<AppendedData", std::string::npos)
                               : ReadUntil(file, "", std::string::npos);
  if (stl)
  {
    return CheckBinarySTL(path, text, bytes, error);
  }
  return legacy ? CheckLegacy(text, bytes, error)
                : ply ? CheckPLY(text, bytes, error) : CheckXML(text, bytes, error);
}
