// The memory a command may use, checked before the work starts: a module estimates what its
// parameters will need and refuses them, naming the figure, when it exceeds the budget (the
// machine's physical memory, or --max-memory).
#pragma once

#include <string>

#include "framework/host/context.h"

namespace voroseal {

/// The machine's physical memory in bytes (0 when unknown).
double machine_memory_bytes();

/// The budget of `context`: its max_memory_bytes when set, else the machine's memory.
double memory_budget_bytes(const Context& context);

/// "4G", "512M", "2.5g", "1000000" (bytes): a size in bytes.
/// \throws ParameterError naming --max-memory when the text is not a positive size.
double parse_memory_size(const std::string& text);

/// "1.5 GB" and the like, for messages.
std::string memory_text(double bytes);

/// \throws ParameterError "`what` needs about X of memory, the budget is Y (...)" when `bytes`
/// exceeds the budget of `context`. A budget of 0 (unknown) accepts everything.
void require_memory(const Context& context, double bytes, const std::string& what);

}  // namespace voroseal
