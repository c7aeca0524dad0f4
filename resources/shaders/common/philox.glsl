// Philox4x32-10 (Salmon et al., SC'11): the GLSL twin of core/common/Philox.h, same rounds, constants
// and counter layout, so a draw for (seed, purpose, subject, sequence) is the same on CPU and GPU.
const uint kPhiloxMul0 = 0xD2511F53u;
const uint kPhiloxMul1 = 0xCD9E8D57u;
const uint kPhiloxWeyl0 = 0x9E3779B9u;
const uint kPhiloxWeyl1 = 0xBB67AE85u;

uvec4 philox4x32(uvec4 ctr, uvec2 key) {
    for (int round = 0; round < 10; ++round) {
        if (round > 0) key += uvec2(kPhiloxWeyl0, kPhiloxWeyl1);
        uint hi0, lo0, hi1, lo1;
        umulExtended(kPhiloxMul0, ctr.x, hi0, lo0);
        umulExtended(kPhiloxMul1, ctr.z, hi1, lo1);
        ctr = uvec4(hi1 ^ ctr.y ^ key.x, lo1, hi0 ^ ctr.w ^ key.y, lo0);
    }
    return ctr;
}

// randomWords(seed, purpose, subject, sequence) with 64-bit seed and sequence as (low, high) words.
uvec4 randomWords(uvec2 seed, uint purpose, uint subject, uvec2 sequence) {
    return philox4x32(uvec4(subject, sequence.x, sequence.y, purpose), seed);
}

// Uniform in (0, 1] from one word; float keeps 24 of its bits, enough for the draws made on the GPU.
float unitOpen32(uint w) {
    return (float(w >> 8) + 0.5) * (1.0 / 16777216.0);
}
