// Transparency / X-ray (thesis 1.3.3, Fig. 5.2): front-to-back compositing of the layers
// the trim walk passes (trim_walk.glsl with TRANSPARENCY). CPU twin: core/trim/
// transparency.h (compositeXray); keep the sequence of operations identical:
//  1. C = 0, T = 1, d = the span start (world distance from the eye);
//  2. a cap: Opaque display -> the cap alone; Translucent -> a layer at the span start;
//  3. each fragment, while T >= 1/512 and no opaque layer was composited: Beer-Lambert
//     over [d, depth] when the interval classifies interior, then C += T*alpha*color,
//     T *= 1 - alpha with the alpha of its role (ghost, layer, opaque, hidden);
//  4. the pixel is C + T*background.
// The shown fragment (the first boundary) and the cap are composited by weight only
// here; emitWalkResult adds weight*color with the highlights once they are known.
// Needs fragment_pack.glsl, trim_shading.glsl, scene_data.glsl, trim_output.glsl and
// clip.glsl (and cap.glsl with CAPPING).

const int XRAY_OPAQUE = 0; // TrimDisplay
const int XRAY_ROLE_HIDDEN = 0; // XrayRole
const int XRAY_ROLE_GHOST = 1;
const int XRAY_ROLE_LAYER = 2;
const int XRAY_ROLE_OPAQUE = 3;
const float XRAY_STOP_TRANSMITTANCE = 1.0 / 512.0;

uniform int u_xrayDisplay;
uniform float u_xrayLayerAlpha;     // clamped to [0, 1]
uniform float u_xrayGhostAlpha;     // clamped to [0, 1]
uniform float u_xrayDensity;        // per world unit, >= 0
uniform float u_xrayFresnel;        // exponent, 0: off

vec3 g_xrayColor = vec3(0.0);
float g_xrayT = 1.0;
float g_xrayLastDepth = 0.0;
float g_xrayRayLength = 1.0;   // world units per unit of view depth along this pixel's ray
float g_xrayShownWeight = 0.0; // T*alpha of the shown fragment
float g_xrayCapWeight = 0.0;   // alpha of the cap
bool g_xrayCap = false;        // the pixel shows a cap
bool g_xrayShown = false;      // a boundary or the cap lies in front
bool g_xrayEnded = false;      // an opaque layer was composited

bool xrayDone() { return g_xrayEnded || g_xrayT < XRAY_STOP_TRANSMITTANCE; }

int xrayRole(bool boundary, bool shownBefore)
{
    if (boundary && u_xrayDisplay == XRAY_OPAQUE)
        return shownBefore ? XRAY_ROLE_HIDDEN : XRAY_ROLE_OPAQUE;
    if (boundary)
        return u_xrayLayerAlpha > 0.0 ? XRAY_ROLE_LAYER : XRAY_ROLE_HIDDEN;
    return u_xrayGhostAlpha > 0.0 ? XRAY_ROLE_GHOST : XRAY_ROLE_HIDDEN;
}

float fresnelAlpha(float alpha, float cosine)
{
    if (u_xrayFresnel <= 0.0 || alpha <= 0.0)
        return alpha;
    return alpha + (1.0 - alpha) * pow(1.0 - clamp(abs(cosine), 0.0, 1.0), u_xrayFresnel);
}

float xrayAlpha(int role, float cosine)
{
    if (role == XRAY_ROLE_GHOST)
        return fresnelAlpha(u_xrayGhostAlpha, cosine);
    if (role == XRAY_ROLE_LAYER)
        return fresnelAlpha(u_xrayLayerAlpha, cosine);
    return role == XRAY_ROLE_OPAQUE ? 1.0 : 0.0;
}

// The usual shading of a stored fragment, without highlights, and |n.v| there.
vec3 xrayShade(uvec2 f, out float cosine)
{
    bool front = fragmentFrontFacing(f);
    vec3 viewPos = pixelRayDirection() * fragmentDepth(f);
    SurfacePoint surface = surfacePoint(fragmentObject(f), fragmentPrimitive(f), viewPos);
    vec3 normal = interpolatedViewNormal(surface);
    vec3 toViewer = normalize(-viewPos);
    cosine = abs(dot(normal, toViewer));
    return u_vertexColors ? shadeColoredPoint(interpolatedColor(surface), front, normal, toViewer)
                          : shadeTrimPoint(front, normal, toViewer);
}

void beginXray(bool startInterior)
{
    vec3 direction = pixelRayDirection();
    g_xrayRayLength = length(direction);
    ClipSpan span = pixelSpan(direction);
    g_xrayLastDepth = span.tStart * g_xrayRayLength;
#ifdef CAPPING
    if (!startInterior || span.empty || span.startSlot < 0)
        return;
    g_xrayCap = true;
    g_xrayShown = true;
    if (u_xrayDisplay == XRAY_OPAQUE) {
        g_xrayCapWeight = 1.0;
        g_xrayT = 0.0;
        g_xrayEnded = true;
        return;
    }
    vec3 toViewer = mat3(u_viewToWorld) * normalize(-direction);
    g_xrayCapWeight = fresnelAlpha(u_xrayLayerAlpha, abs(dot(u_capNormalsWorld[span.startSlot], toViewer)));
    g_xrayT = 1.0 - g_xrayCapWeight;
#endif
}

// One fragment of the span, in walk order. `first`: the shown fragment (composited by
// weight; its color comes with the highlights in xrayPixelColor) unless a cap is shown.
void xrayFragment(uvec2 fragment, bool boundary, bool interiorBefore, bool first)
{
    if (xrayDone())
        return;
    float depth = fragmentDepth(fragment) * g_xrayRayLength;
    if (interiorBefore && u_xrayDensity > 0.0 && depth > g_xrayLastDepth)
        g_xrayT *= exp(-u_xrayDensity * (depth - g_xrayLastDepth));
    g_xrayLastDepth = depth;
    int role = xrayRole(boundary, g_xrayShown);
    g_xrayShown = g_xrayShown || boundary;
    if (role == XRAY_ROLE_HIDDEN)
        return;
    bool deferred = first && !g_xrayCap;
    float cosine = 1.0;
    // The shown fragment is shaded once, in emitShownPixel; here only its alpha's |n.v|.
    vec3 color = deferred && role == XRAY_ROLE_OPAQUE ? vec3(0.0) : xrayShade(fragment, cosine);
    float alpha = xrayAlpha(role, cosine);
    if (deferred)
        g_xrayShownWeight = g_xrayT * alpha;
    else
        g_xrayColor += g_xrayT * alpha * color;
    g_xrayT *= 1.0 - alpha;
    g_xrayEnded = role == XRAY_ROLE_OPAQUE;
}

// The pixel's composited color: `shownColor` is the shown fragment's color with its
// highlights (or the cap's color when the pixel shows a cap).
vec3 xrayPixelColor(vec3 shownColor)
{
    float weight = g_xrayCap ? g_xrayCapWeight : g_xrayShownWeight;
    return g_xrayColor + weight * shownColor + g_xrayT * BACKGROUND_COLOR;
}
