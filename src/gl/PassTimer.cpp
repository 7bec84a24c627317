#include "gl/PassTimer.hpp"

#include <chrono>
#include <ctime>

namespace og::gl {

void PassTimer::beginFrame() {
  used_ = 0;
  names_.clear();
  cpuMs_.clear();
  stamp();
  names_.push_back(nullptr);
}

void PassTimer::stamp() {
  if (mode_ == Mode::Queries) {
    if (used_ == queries_.size()) queries_.push_back(createQuery(GL_TIMESTAMP));
    glQueryCounter(queries_[used_].id(), GL_TIMESTAMP);
  } else if (mode_ == Mode::Finish) {
    glFinish();
    cpuMs_.push_back(std::chrono::duration<double, std::milli>(
                         std::chrono::steady_clock::now().time_since_epoch()).count());
  } else {
    glFinish();
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    cpuMs_.push_back(static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) * 1e-6);
  }
  ++used_;
}

void PassTimer::mark(const char* pass) {
  stamp();
  names_.push_back(pass);
}

void PassTimer::endFrame() {
  stamp();
  names_.push_back(nullptr);
}

std::vector<std::pair<std::string, double>> PassTimer::results() {
  std::vector<double> at(used_);
  for (std::size_t i = 0; i < used_; ++i) {
    if (mode_ != Mode::Queries) {
      at[i] = cpuMs_[i];
    } else {
      GLuint64 ns = 0;
      glGetQueryObjectui64v(queries_[i].id(), GL_QUERY_RESULT, &ns);
      at[i] = static_cast<double>(ns) * 1e-6;
    }
  }
  std::vector<std::pair<std::string, double>> out;
  for (std::size_t i = 0; i + 1 < used_; ++i) {
    if (names_[i] == nullptr) continue;
    const double ms = at[i + 1] - at[i];
    bool merged = false;
    for (auto& [name, total] : out)
      if (name == names_[i]) {
        total += ms;
        merged = true;
      }
    if (!merged) out.emplace_back(names_[i], ms);
  }
  return out;
}

}  // namespace og::gl
