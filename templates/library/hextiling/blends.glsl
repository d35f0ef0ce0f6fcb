// x^n for a literal n in 1..16 by repeated squaring: hexc passes n when an exponent is a whole number, the
// optimiser folds the branches, and gamma = 7 costs four multiplications instead of a pow (exp2 and log2).
vec3 hexcPowInt(vec3 x, int n) {
    vec3 r = vec3(1.0);
    if ((n & 1) != 0) r *= x;
    x *= x;
    if ((n & 2) != 0) r *= x;
    x *= x;
    if ((n & 4) != 0) r *= x;
    x *= x;
    if ((n & 8) != 0) r *= x;
    x *= x;
    if ((n & 16) != 0) r *= x;
    return r;
}

// Listing 8 / Eq. 5: Perlin's gain g with k = log(1 - r) / log(1/2). kInt > 0: k is that whole number
// (r = 1 - 2^-k, e.g. the paper's 0.75 gives k = 2), a literal chosen by hexc.
float hexcGainK(float r, int kInt) {
    return kInt > 0 ? float(kInt) : log(1.0 - r) / log(0.5);
}

vec3 hexcGainCurve(vec3 x, float r, int kInt) {
    vec3 s = 2.0 * step(0.5, x);
    vec3 m = 2.0 * (1.0 - s);
    vec3 base = max(vec3(0.0), s + x * m);
    return 0.5 * s + 0.25 * m * (kInt > 0 ? hexcPowInt(base, kInt) : pow(base, vec3(hexcGainK(r, kInt))));
}

// The gain, then renormalised.
vec3 hexcGain3(vec3 x, float r, int kInt) {
    vec3 res = hexcGainCurve(x, r, kInt);
    return res / (res.x + res.y + res.z);
}

// How a slot weighs its tiles' samples, filled by each generated slot function from hexcBlend() (the neutral
// values). Fields marked "literal" are set from constants chosen by hexc: metric and gain are false when
// falloffcontrast is 0 or falloff is 0.5, so that the metric (and the samples' luminance) or the gain is not
// emitted instead of computing a no-op; a whole-number exponent or gain exponent (> 0) replaces a pow.
struct HexcBlend {
    float falloff;               // r of Eq. 5 / Listing 8
    float falloffContrast;       // beta of Eq. 3-4
    float exponent;              // gamma of Eq. 1
    bool metric;                 // literal: the falloff metric is computed
    bool gain;                   // literal: the gain is applied
    int exponentInt;             // literal: > 0, gamma is this whole number (multiplied out); 0: a pow per pixel
    int gainInt;                 // literal: > 0, the gain's k is this whole number; 0 with gain: a log and a pow
    int taps;                    // literal: 3, 2 for the checker mask (no third fetch); 1 dithered
    bool sharedLod;              // literal: lod "shared", every fetch at the slot's level of detail (hexcTileLods)
    bool adaptive;               // literal: "taps": "adaptive", fetch a tap only when it can matter (hexcAdaptiveTaps)
    float adaptiveError;         // literal: the bound it keeps, epsilon below
    bool height;                 // literal: blend by the heights in channel heightLuma of the height texture
    vec4 heightLuma;
    float heightWidth;
};

HexcBlend hexcBlend() {
    return HexcBlend(0.5, 0.0, 7.0, false, false, 0, 0, 3, false, false, 1.0 / 255.0, false, vec4(0.0), 1.0);
}

// The falloff metric's factor of each tap (Eqs. 3-4) from its luminance, channel or slope Dw; 1 without the metric.
// A negative metric (HDR texels with negative values) counts as 0.
vec3 hexcMetric(vec3 Dw, HexcBlend b) {
    return b.metric ? mix(vec3(1.0), max(Dw, vec3(0.0)), b.falloffContrast) : vec3(1.0);
}

// The tiles' weights from the lattice's w, each tap's metric factor M (hexcMetric) and the gain. A guard keeps them
// finite and normalised outside the paper's domain, and changes nothing inside it: when every weighted term is 0
// (falloffcontrast 1 over three black samples) the metric is ignored.
vec3 hexcBlendWeights(vec3 w, vec3 M, HexcBlend b) {
    vec3 wg = b.exponentInt > 0 ? hexcPowInt(w, b.exponentInt) : pow(w, vec3(b.exponent));
    vec3 W = M * wg;
    float sum = W.x + W.y + W.z;
    W = sum > 0.0 ? W / sum : wg / (wg.x + wg.y + wg.z);
    if (b.gain && (b.gainInt > 0 || b.falloff != 0.5)) W = hexcGain3(W, b.falloff, b.gainInt);
    return W;
}

// Adaptive taps ("taps": "adaptive", docs/material-format.md#taps): which taps to fetch, decided from the lattice
// weights alone, before any sample, so that the result moves by at most e = b.adaptiveError against all three.
// With wg = w^gamma, the metric D_i in [1 - beta, 1] (luminance or channel in [0, 1]; a normal's slope sine always),
// W = D wg / sum(D wg), and the final weights G = g(W) / sum(g(W)) (g the gain, monotone):
//   W_i <= U_i = wg_i / (wg_i + (1 - beta) sum_{j != i} wg_j)     (D_i = 1, the others 1 - beta)
//   W_i >= L_i = (1 - beta) wg_i / ((1 - beta) wg_i + sum_{j != i} wg_j)
//   G_i <= Gup_i = g(U_i) / (g(U_i) + sum_{j != i} g(L_j))       (G_i rises with W_i, falls with the others)
// A skipped tap gets wg_i = 0: the rest of the blend renormalises itself. The result moves by sum_j |G_j - G'_j| / 2
// (the total variation TV) times the spread of the taps' values (<= 1 for values in [0, 1]). Two taps skipped:
// G' = (1, 0, 0), TV = G_a + G_b <= Gup_a + Gup_b. One skipped (i): TV <= G_i + the gain's change on the two kept,
// whose pre-gain weights grow by 1 / (1 - W_i): each g(cW) / g(W) lies in [1, c^k] (g's elasticity x g'(x) / g(x) is
// in [0, k] for k >= 1, which the parser requires), so the kept pair's log-odds move by at most k ln c, their share
// by at most a quarter of that (the logistic's slope): TV <= Gup_i + k/4 ln(1 / (1 - U_i)). Without the gain, g(x) = x
// and k = 0.
// The heaviest tap (largest w) is always fetched; the other two together when Gup_a + Gup_b < e, else the one
// with the smaller bound when that is < e.
bvec3 hexcAdaptiveTaps(vec3 w, HexcBlend b) {
    // The bounds need only the weights' ratios: w over its largest keeps the largest wg at 1, where w^gamma itself
    // (down to (1/3)^64 ~ 3e-31) would fall below the guards' 1e-30 and float32's normal range. A wg that underflows
    // still has U_i < 2^-126 / (1 - beta): nothing.
    vec3 wn = w / max(max(w.x, w.y), max(w.z, 1e-30));
    vec3 wg = b.exponentInt > 0 ? hexcPowInt(wn, b.exponentInt) : pow(wn, vec3(b.exponent));
    float lo = b.metric ? 1.0 - b.falloffContrast : 1.0;
    vec3 others = vec3(wg.x + wg.y + wg.z) - wg;
    vec3 U = wg / max(wg + lo * others, vec3(1e-30));
    vec3 L = lo * wg / max(lo * wg + others, vec3(1e-30));
    vec3 gU = U, gL = L;
    float k = 0.0;
    if (b.gain && (b.gainInt > 0 || b.falloff != 0.5)) {
        gU = hexcGainCurve(U, b.falloff, b.gainInt);
        gL = hexcGainCurve(L, b.falloff, b.gainInt);
        k = hexcGainK(b.falloff, b.gainInt);
    }
    vec3 Gup = gU / max(gU + vec3(gL.x + gL.y + gL.z) - gL, vec3(1e-30));
    // Where the gain is a pure power for tap i and the others (all three arguments below 0.5: g(x) = 0.5 (2x)^k), g
    // underflows float32 (0.01^19 = 1e-38) and the guard above would shrink Gup_i; the ratio does not: take it before
    // the power. U_i = 0 gives an infinite ratio, Gup_i = 0.
    if (k > 0.0) {
        vec3 r1 = L.yzx / max(U, vec3(1e-30)), r2 = L.zxy / max(U, vec3(1e-30));
        vec3 p1 = b.gainInt > 0 ? hexcPowInt(r1, b.gainInt) : pow(r1, vec3(k));
        vec3 p2 = b.gainInt > 0 ? hexcPowInt(r2, b.gainInt) : pow(r2, vec3(k));
        Gup = mix(Gup, 1.0 / (1.0 + p1 + p2), lessThan(max(U, max(L.yzx, L.zxy)), vec3(0.5)));
    }
    // U_i = 1 only for a tap whose weight cannot be bounded: never skipped, so its term may be infinite.
    vec3 B = Gup - 0.25 * k * log(max(vec3(1.0) - U, vec3(1e-30)));
    int d = w.x >= w.y && w.x >= w.z ? 0 : (w.y >= w.z ? 1 : 2);
    int a = d == 0 ? 1 : 0, c = d == 2 ? 1 : 2;
    bvec3 f = bvec3(true);
    if (Gup[a] + Gup[c] < b.adaptiveError) {
        f[a] = false;
        f[c] = false;
    } else if (min(B[a], B[c]) < b.adaptiveError) {
        f[B[a] <= B[c] ? a : c] = false;
    }
    return f;
}
