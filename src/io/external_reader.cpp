#include "io/external_reader.hpp"

#include <memory>

namespace hoct {
namespace {

std::unique_ptr<ExternalReader> &registered() {
  static std::unique_ptr<ExternalReader> r;
  return r;
}

} // namespace

void set_external_reader(ExternalReader reader) {
  registered() = std::make_unique<ExternalReader>(std::move(reader));
}

const ExternalReader *external_reader() { return registered().get(); }

} // namespace hoct
