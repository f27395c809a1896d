// The order in which the GPU engine's bands of rows cover a frame, written once for the engine (which plans
// the bands: Engine/BandPlan.h) and its shaders (which find their pixel: launchPixel() in Bindings.glsl).
//
// A batch that one submission would make too long is traced in bands of rows, and the next band is sized by
// the time the last one took. Bands of consecutive rows measured the top of the frame (often sky) and sized
// the next band of its lower rows from it: with a growth of 64 that band ran 1.6 s past a Ctrl-C on lavapipe.
// In the interleaved order every band is spread over the whole frame, so its time tells the next band's.
#ifndef RT_SHARED_BAND_ORDER_H
#define RT_SHARED_BAND_ORDER_H

#include "Shared/HostDevice.h"
#include "Shared/ShaderLang.h"

RT_SHADER_NAMESPACE_BEGIN

/// The interleave of a batch cut into several bands: one pass of the order (ceil(height / 16) rows) holds
/// every sixteenth row of the frame, and any band of a pass or more (a capped first band of a frame, most
/// often) holds a row of every whole block of sixteen rows, top to bottom.
RT_CONST(uint, kBandInterleave, 16u)

/// The image row at position `j` (< height) of a frame's row order: with `interleave` k > 1, the rows r with
/// r mod k = 0 first, top to bottom, then those with r mod k = 1, and so on; with k <= 1, row j. A bijection
/// of [0, height) for any height >= 1 (height < k included).
RT_FN uint bandOrderRow(uint j, uint height, uint interleave)
{
    if (interleave <= 1u)
        return j;
    const uint shortPhase = height / interleave; // rows of the phases r mod k >= height mod k
    const uint longPhases = height % interleave; // the phases before them hold one row more
    const uint longRows = longPhases * (shortPhase + 1u);
    if (j < longRows)
        return j / (shortPhase + 1u) + (j % (shortPhase + 1u)) * interleave;
    const uint rest = j - longRows; // here shortPhase >= 1, since j < height
    return longPhases + rest / shortPhase + (rest % shortPhase) * interleave;
}

RT_SHADER_NAMESPACE_END

#endif
