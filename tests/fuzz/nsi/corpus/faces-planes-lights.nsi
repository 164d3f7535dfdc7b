Create "cam" "orthographiccamera" Connect "cam" "" ".root" "objects"
Create "scr" "screen" Connect "scr" "" "cam" "screens"
SetAttribute "scr" "resolution" "int[2]" 1 [ 4 4 ] "oversampling" "int" 1 1
Create "m" "mesh" Connect "m" "" ".root" "objects"
SetAttribute "m" "nvertices" "int" 3 [ 4 4 3 ] "nholes" "int" 2 [ 1 0 ]
  "P" "point" 11 [ -1 -1 0 1 -1 0 1 1 0 -1 1 0  -0.5 -0.5 0 -0.5 0.5 0 0.5 0.5 0 0.5 -0.5 0  2 0 0 3 0 0 2 1 0 ]
Create "fs" "faceset" Connect "fs" "" "m" "facesets" SetAttribute "fs" "faces" "int" 1 1
Create "s" "shader" SetAttribute "s" "shaderfilename" "string" 1 "dlPrincipled" "i_color" "color" 1 [ 1 0 0 ]
Create "a" "attributes" Connect "s" "" "a" "surfaceshader" Connect "a" "" "fs" "geometryattributes"
SetAttribute "a" "visibility.camera" "int" 1 0 "visibility.camera.priority" "int" 1 3
Create "g" "plane" Connect "g" "" ".root" "objects"
Create "spot" "particles" Connect "spot" "" ".root" "objects"
SetAttribute "spot" "P" "point" 1 [ 0 3 0 ] "N" "normal" 1 [ 0 -1 0 ] "width" "float" 1 0.1
Create "sl" "shader" SetAttribute "sl" "shaderfilename" "string" 1 "spotLight" "coneAngle" "float" 1 30
Create "sa" "attributes" Connect "sl" "" "sa" "surfaceshader" Connect "sa" "" "spot" "geometryattributes"
Create "sky" "environment" Connect "sky" "" ".root" "objects"
Create "el" "shader" SetAttribute "el" "shaderfilename" "string" 1 "environmentLight" "image" "string" 1 "${HOME}/none.exr"
Create "ea" "attributes" Connect "el" "" "ea" "surfaceshader" Connect "ea" "" "sky" "geometryattributes"
RenderControl "action" "string" 1 "start" RenderControl "action" "string" 1 "wait"
