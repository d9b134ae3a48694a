#include "meshing/gmsh_session.hpp"

#include <gmsh.h>
#include <exception>
#include <stdexcept>
#include <vector>

#include "core/errors.hpp"
#include "core/log.hpp"

namespace sf {

GmshSession::GmshSession() {
  try {
    gmsh::initialize(0, nullptr, /*readConfigFiles=*/false);  // no user gmshrc: deterministic
    gmsh::option::setNumber("General.Terminal", verbosity() >= Verbosity::verbose ? 1 : 0);
    gmsh::option::setNumber("General.AbortOnError", 2);  // errors throw instead of going on
    gmsh::option::setNumber("General.NumThreads", 1);    // serial and deterministic
    gmsh::logger::start();
  } catch (...) {
    throw std::runtime_error("gmsh could not be initialised");
  }
}

GmshSession::~GmshSession() {
  try {
    gmsh::logger::stop();
  } catch (...) {
  }
  try {
    gmsh::finalize();
  } catch (...) {
  }
}

std::string GmshSession::logged_errors() {
  std::vector<std::string> log;
  try {
    gmsh::logger::get(log);
  } catch (...) {
    return {};
  }
  std::string text;
  auto add = [&text](const std::string& line) { text += (text.empty() ? "" : "\n") + line; };
  for (const auto& line : log) {
    if (line.rfind("Error", 0) == 0) {
      add(line);
    }
    // gmsh only notes a repeated node tag in a .msh and keeps the first node's coordinates: the
    // mesh is not what the file says.
    const std::size_t duplicate = line.find("Skipping duplicate node ");
    if (duplicate != std::string::npos) {
      add("Error: node tag " + line.substr(duplicate + 24) +
          " appears more than once (gmsh keeps the first coordinates and drops the others)");
    }
  }
  return text;
}

void run_gmsh_step(const std::filesystem::path& file, const std::string& step,
                   const std::function<void()>& body) {
  std::string thrown;
  bool failed = false;
  try {
    body();
  } catch (const InputError&) {
    throw;
  } catch (const std::bad_alloc&) {
    throw;  // the job reports the memory limit
  } catch (const std::string& s) {
    failed = true;
    thrown = s;
  } catch (const char* s) {
    failed = true;
    thrown = s ? s : "";
  } catch (const std::exception& e) {
    failed = true;
    thrown = e.what();
  } catch (...) {
    failed = true;
    thrown = "unknown gmsh exception";
  }
  const std::string logged = GmshSession::logged_errors();
  if (!failed && logged.empty()) {
    return;
  }
  std::string message = "'" + file.string() + "': gmsh failed while " + step;
  if (!logged.empty()) {
    message += ":\n" + logged;
  }
  if (!thrown.empty() && logged.find(thrown) == std::string::npos) {
    message += (logged.empty() ? ": " : "\n") + thrown;
  }
  throw InputError(message);
}

}  // namespace sf
