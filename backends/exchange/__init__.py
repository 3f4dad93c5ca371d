"""Exchange formats: targets that write documents other tools read (MaterialX, USD, Mitsuba).

Targets:    materialx.py (+ materialx_native.py, MaterialX node recipes for maps=native),
            usd.py (+ usd_stage.py, a phrase authored into an existing stage),
            mitsuba.py (+ mitsuba_cnlm.py, the Mitsuba plugin running cnlmc's BSDF).
Shared:     naming.py (identifiers and XML-safe text), conversions.py (IR parameters -> the
            conductor colours and roughness fits exchange shaders take), surface_inputs.py
            (IR material -> MaterialX surface-shader inputs, used by MaterialX and USD),
            options.py (the options every exchange target takes), textures.py (baked maps
            as image files a document references).
Templates:  templates/mitsuba/*.j2.
"""
