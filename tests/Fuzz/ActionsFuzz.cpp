// Fuzz target: the windows' --actions grammar (Cli/ActionGrammar.h) with the actions both windows share, and
// each parsed value read as its kind.
#include "Cli/ActionGrammar.h"
#include "Error.h"
#include "Fuzz/FuzzInput.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    static const std::vector<rt::ActionSpec> specs = rt::sharedActionSpecs("samples per pixel", 1);
    try
    {
        for (const rt::ScriptedAction& action : rt::parseActionScript(rt::fuzz::text(data, size), specs))
            for (const rt::ActionSpec& spec : specs)
                if (spec.name == action.name)
                    switch (spec.value)
                    {
                    case rt::ActionValue::Integer:
                        (void)action.integer();
                        break;
                    case rt::ActionValue::Real:
                        (void)action.real();
                        break;
                    case rt::ActionValue::OnOff:
                        (void)action.on();
                        break;
                    case rt::ActionValue::Size:
                        (void)action.size();
                        break;
                    default:
                        break;
                    }
    }
    catch (const rt::Error&)
    {
    }
    return 0;
}
