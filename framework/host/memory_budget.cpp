#include "framework/host/memory_budget.h"

#include <unistd.h>

#include <cctype>
#include <cmath>
#include <cstdio>

#include "framework/core/error.h"

namespace voroseal {

double machine_memory_bytes() {
  const long pages = ::sysconf(_SC_PHYS_PAGES);
  const long page = ::sysconf(_SC_PAGE_SIZE);
  return pages > 0 && page > 0 ? static_cast<double>(pages) * static_cast<double>(page) : 0.0;
}

double memory_budget_bytes(const Context& context) {
  return context.max_memory_bytes > 0.0 ? context.max_memory_bytes : machine_memory_bytes();
}

double parse_memory_size(const std::string& text) {
  size_t used = 0;
  double value = 0.0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  double unit = 1.0;
  if (used > 0 && used + 1 == text.size()) {
    switch (std::tolower(static_cast<unsigned char>(text.back()))) {
      case 'k':
        unit = 1024.0;
        break;
      case 'm':
        unit = 1024.0 * 1024.0;
        break;
      case 'g':
        unit = 1024.0 * 1024.0 * 1024.0;
        break;
      case 't':
        unit = 1024.0 * 1024.0 * 1024.0 * 1024.0;
        break;
      default:
        used = 0;
    }
    if (used > 0) ++used;
  }
  if (used == 0 || used != text.size() || !std::isfinite(value) || !(value > 0.0))
    throw ParameterError(
        "--max-memory: expected a positive size such as 4G, 512M or 1000000, got '" + text + "'");
  return value * unit;
}

std::string memory_text(double bytes) {
  const char* units[] = {"bytes", "KB", "MB", "GB", "TB", "PB"};
  int u = 0;
  while (bytes >= 1024.0 && u < 5) bytes /= 1024.0, ++u;
  char text[64];
  std::snprintf(text, sizeof text, u == 0 ? "%.0f %s" : "%.3g %s", bytes, units[u]);
  return text;
}

void require_memory(const Context& context, double bytes, const std::string& what) {
  const double budget = memory_budget_bytes(context);
  if (budget <= 0.0 || !(bytes > budget)) return;
  const bool machine = !(context.max_memory_bytes > 0.0);
  throw ParameterError(
      what + " needs about " + memory_text(bytes) + " of memory, more than " +
      (machine ? "this machine has (" + memory_text(budget) + "; --max-memory SIZE allows more)"
               : "--max-memory (" + memory_text(budget) + ")"));
}

}  // namespace voroseal
