// RenderRequest::camera on the CPU engine (the windows' moved camera): tests/Support/MovedCamera.h.
#include <gtest/gtest.h>

#include <memory>

#include "Engine/CpuEngine.h"
#include "RenderTestSupport.h"
#include "Support/MovedCamera.h"

namespace rt::test
{
namespace
{
TEST(CpuRequestCamera, RendersTheRequestsCameraAndForgetsItAfterwards)
{
    cpu::CpuEngine engine(EngineKind::Multi);
    expectTheRequestsCameraIsRendered(engine, "rtrol-cornell-box", smallSettings(32, 4, 8, Estimator::NeeMis),
                                      [] { return std::make_unique<cpu::CpuEngine>(EngineKind::Multi); });
}
} // namespace
} // namespace rt::test
