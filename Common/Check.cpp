#include "Check.h"

#include <cstdlib>
#include <memory>

#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

namespace rt::detail
{
void checkFailed(const char* file, int line, std::string_view message)
{
    // spdlog's default logger writes to stdout: flush what it holds, then report on a stderr logger of our
    // own (the apps' "level: message" pattern), so the line lands where errors go and death tests see it.
    if (spdlog::logger* defaultLogger = spdlog::default_logger_raw())
        defaultLogger->flush();
    spdlog::logger logger("check", std::make_shared<spdlog::sinks::stderr_color_sink_st>());
    logger.set_pattern("%^%l%$: %v");
    logger.critical("{}:{}: check failed: {}", file, line, message);
    logger.flush();
    std::abort();
}
} // namespace rt::detail
