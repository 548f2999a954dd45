// Numbers as JSON text, appended to a string: what nlohmann::json's dump() writes for them, at a
// fraction of its cost per value (the tree writer's arrays hold millions of them). Doubles are
// written in their shortest round-trip digits (std::to_chars) laid out as nlohmann lays out its
// own (integral values end in ".0"; fixed notation for decimal exponents -4 .. 15, else
// d.ddde+XX); a value that is not finite is null, as nlohmann writes it.
#pragma once

#include <cstdint>
#include <string>

namespace hoct {

void append_json_int(std::string &out, int64_t value);
void append_json_double(std::string &out, double value);

} // namespace hoct
