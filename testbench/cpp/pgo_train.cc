// The training run of the profile-guided build of the Verilated models (build/pgo.rs,
// docs/performance.md): replays pin inputs on the models built with -fprofile-instr-generate.
// Usage: pgo_train CHIP FILE [CHIP FILE ...]; CHIP 0 TMC428, 1 TMC429, 2 TMC4210; FILE holds
// one little-endian 16-bit word per CLK edge: bit 0 nSCS_C, 1 SCK_C, 2 SDI_C, 3 SDI_S,
// 4..6 REF1..3, 7..9 REFR1..3, 10 rst.
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "verilated.h"
#include "Vtmc429_428.h"
#include "Vtmc429_429.h"
#include "Vtmc429_4210.h"
#include "Vtmc429_428___024root.h"
#include "Vtmc429_429___024root.h"
#include "Vtmc429_4210___024root.h"
#include "vl_pins.h"

TMC429_VL_POSEDGE(Vtmc429_428)
TMC429_VL_POSEDGE(Vtmc429_429)
TMC429_VL_POSEDGE(Vtmc429_4210)

namespace {

struct Pins {
    bool nscs_c, sck_c, sdi_c, sdi_s, ref1, ref2, ref3, refr1, refr2, refr3;
};

template <class V>
bool replay(const char *path) {
    std::ifstream f(path, std::ios::binary | std::ios::ate);
    const std::streamoff n = f ? static_cast<std::streamoff>(f.tellg()) : -1;
    std::vector<char> bytes(n > 0 ? static_cast<size_t>(n) : 0);
    if (n >= 0) f.seekg(0).read(bytes.data(), n);
    if (!f || n < 0 || n % 2 != 0) {
        std::fprintf(stderr, "pgo_train: %s: not a file of 16-bit words\n", path);
        return false;
    }
    VerilatedContext ctx;
    V t(&ctx, "rtl");
    tmc429tb::reset_edge(t);
    for (size_t k = 0; k < bytes.size(); k += 2) {
        const unsigned w = static_cast<unsigned char>(bytes[k]) | (static_cast<unsigned char>(bytes[k + 1]) << 8);
        auto bit = [w](int b) { return static_cast<bool>((w >> b) & 1); };
        const Pins p{bit(0), bit(1), bit(2), bit(3), bit(4), bit(5), bit(6), bit(7), bit(8), bit(9)};
        tmc429tb::set_inputs(t, p);
        t.rst = bit(10);
        tmc429tb::falling_edge(t);
        tmc429tb::rising_edge<true>(t);
    }
    t.final();
    return true;
}

}  // namespace

int main(int argc, char **argv) {
    if (argc < 3 || argc % 2 == 0) {
        std::fprintf(stderr, "usage: pgo_train CHIP FILE [CHIP FILE ...]\n");
        return 2;
    }
    for (int a = 1; a < argc; a += 2) {
        const std::string chip = argv[a];
        bool ok = chip == "0"   ? replay<Vtmc429_428>(argv[a + 1])
                  : chip == "1" ? replay<Vtmc429_429>(argv[a + 1])
                  : chip == "2" ? replay<Vtmc429_4210>(argv[a + 1])
                                : false;
        if (!ok) return 1;
    }
    return 0;
}
