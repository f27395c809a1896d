# Sourced by the window tests of this folder: what every run of the app is checked for, and the screenshots
# kept for a person.

# check_run NAME STATUS ERRFILE: fails, showing the app's stderr, if it exited non-zero or the validation
# layer reported anything.
check_run() {
    local name=$1 status=$2 err=$3
    if [ "$status" -ne 0 ]; then
        tail -20 "$err"; echo "FAIL: $name exited with status $status"; exit 1
    fi
    if grep -q "Vulkan validation" "$err"; then
        grep "Vulkan validation" "$err" | head; echo "FAIL: $name: the validation layer reported something"; exit 1
    fi
}

# keep_pngs DIR: copies DIR's screenshots to $RT_GUI_KEEP when it is set.
keep_pngs() {
    if [ -n "${RT_GUI_KEEP:-}" ]; then cp "$1"/*.png "$RT_GUI_KEEP"/; fi
}
