// hexc material `${material}` for Unity's Universal Render Pipeline (docs/engines.md#unity): URP's own PBR lighting
// (UniversalFragmentPBR) with the surface from hexc's functions in ${material}.hexc.hlsl, kept beside this file.
Shader "hexc/${material}"
{
    Properties
    {
${properties}
    }
    SubShader
    {
        Tags { "RenderType" = "Opaque" "RenderPipeline" = "UniversalPipeline" }
        Pass
        {
            Name "ForwardLit"
            Tags { "LightMode" = "UniversalForward" }
            HLSLPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
            #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Lighting.hlsl"
            #include "Packages/com.unity.render-pipelines.core/ShaderLibrary/Texture.hlsl"  // UnityTexture2D, for the node entry points
            #include "${material}.hexc.hlsl"

${textures}

            struct Attributes
            {
                float4 positionOS : POSITION;
                float3 normalOS : NORMAL;
                float4 tangentOS : TANGENT;
                float2 uv : TEXCOORD0;
                float4 color : COLOR;  // the mesh's vertex colour, linear: what layers weighed by it read
            };

            struct Varyings
            {
                float4 positionCS : SV_POSITION;
                float3 positionWS : TEXCOORD0;
                float3 normalWS : TEXCOORD1;
                float4 tangentWS : TEXCOORD2;  // w: the bitangent's sign
                float2 uv : TEXCOORD3;
                float4 color : COLOR;
            };

            Varyings vert(Attributes input)
            {
                VertexPositionInputs position = GetVertexPositionInputs(input.positionOS.xyz);
                VertexNormalInputs normal = GetVertexNormalInputs(input.normalOS, input.tangentOS);
                Varyings output;
                output.positionCS = position.positionCS;
                output.positionWS = position.positionWS;
                output.normalWS = normal.normalWS;
                output.tangentWS = float4(normal.tangentWS, input.tangentOS.w * GetOddNegativeScale());
                output.uv = input.uv;
                output.color = input.color;
                return output;
            }

            half4 frag(Varyings input) : SV_Target
            {
                // Unity's uv: (0, 0) at the bottom-left, v up; ${uvnote}
                float2 uv = ${uv};
                SurfaceData surface = (SurfaceData)0;
                surface.albedo = half3(1.0, 1.0, 1.0);
                surface.smoothness = 0.5;
                surface.occlusion = 1.0;
                surface.alpha = 1.0;
                surface.normalTS = half3(0.0, 0.0, 1.0);
${inputs}
                // The bitangent along +v (up the image), as hexc's tangent-space normal's y.
                float3 bitangent = input.tangentWS.w * cross(input.normalWS, input.tangentWS.xyz);
                InputData inputData = (InputData)0;
                inputData.positionWS = input.positionWS;
                inputData.normalWS = normalize(TransformTangentToWorld(surface.normalTS, half3x3(input.tangentWS.xyz, bitangent, input.normalWS)));
                inputData.viewDirectionWS = GetWorldSpaceNormalizeViewDir(input.positionWS);
                return UniversalFragmentPBR(inputData, surface);
            }
            ENDHLSL
        }
    }
}
