// The loads file (include/ogive/model/loads_file.hpp): every refusal names its line; headers in any case,
// spaces, CRLF and trailing blank lines are ordinary input.
#include <doctest/doctest.h>

#include <sstream>
#include <stdexcept>
#include <string>

#include "ogive/model/loads_file.hpp"

using namespace ogive;

TEST_CASE("whole arches: a loads file's errors name the line") {
  auto refused_at = [](const std::string& text, const std::string& where) {
    std::istringstream in(text);
    CAPTURE(text);
    try {
      parse_loads(in, "loads.csv");
      FAIL("accepted");
    } catch (const std::invalid_argument& e) {
      CHECK(std::string(e.what()).rfind(where, 0) == 0);
    }
  };
  refused_at("", "loads.csv:1:");
  refused_at("kind,value\n", "loads.csv:1:");
  refused_at("kind,value,a,b\npoint,1e4,1.5,\n", "loads.csv:2:");
  refused_at("kind,value,a,b\npoint,1e4,0.5,\nlive,1e3,0.7,0.2\n", "loads.csv:3:");
  refused_at("kind,value,a,b\nfill,-1,0.5,\n", "loads.csv:2:");
  refused_at("kind,value,a,b\nfill,1800,0,\n", "loads.csv:2:");
  refused_at("kind,value,a,b\nwind,1,0.5,\n", "loads.csv:2:");
  refused_at("kind,value,a,b\npoint,abc,0.5,\n", "loads.csv:2:");
  std::istringstream ok("Kind, Value, A, B\r\npoint,1e4,0.25,\r\nlive,5e3,0,0.5\r\nfill,1800,0.6,\r\n\r\n");
  const Loads loads = parse_loads(ok, "ok.csv");
  CHECK(loads.points.size() == 1);
  CHECK(loads.live.size() == 1);
  CHECK(loads.fills.size() == 1);
  CHECK(loads.live[0].to == 0.5);
}
