// The host's cores for work split in parts: the PNG's compression (Image/ParallelDeflate.h), its rows' filtering
// (Image/ImageIO.cpp), the pilot's scoring (Compare/AutoStrategy.cpp). Plain threads, one per part: the parts are
// few and long, so a pool would add nothing.
#pragma once

#include <functional>

namespace rt
{
/// The number of cores this process may run on (its affinity mask on Linux, else the hardware's threads), at
/// least 1.
int usableCores();

/// Runs work(part) for part in [0, parts) on parts threads (the calling thread takes the last) and returns when
/// all have. Precondition: parts >= 1. An exception thrown by a part is rethrown here.
void runInParallel(int parts, const std::function<void(int part)>& work);
} // namespace rt
