Create "cam" "perspectivecamera" Connect "cam" "" ".root" "objects"
SetAttribute "cam" "fov" "float" 1 30 "shutterrange" "double" 2 [ 0 1 ]
Create "scr" "screen" Connect "scr" "" "cam" "screens"
SetAttribute "scr" "resolution" "int[2]" 1 [ 8 8 ] "crop" "float[2]" 2 [ 0.1 0.2 0.9 0.8 ]
  "screenwindow" "double[2]" 2 [ -1 -1 2 1 ]
Create "xf" "transform" Connect "xf" "" ".root" "objects"
SetAttributeAtTime "xf" 0 "transformationmatrix" "doublematrix" 1 [ 1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1 ]
SetAttributeAtTime "xf" 1 "transformationmatrix" "doublematrix" 1 [ 1 0 0 0 0 1 0 0 0 0 1 0 1 0 0 1 ]
Create "many" "instances" Connect "many" "" "xf" "objects"
Create "m" "mesh" Connect "m" "" "many" "sourcemodels" "index" "int" 1 0
SetAttribute "m" "nvertices" "int" 2 [ 3 4 ] "P" "point" 5 [ 0 0 0 1 0 0 1 1 0 0 1 0 2 2 0 ]
  "P.indices" "int" 7 [ 0 1 2 0 2 3 4 ] "N" "normal" 1 [ 0 0 1 ]
SetAttribute "many" "transformationmatrices" "doublematrix" 2 [ 1 0 0 0 0 1 0 0 0 0 1 0 0 0 -5 1
  1 0 0 0 0 1 0 0 0 0 1 0 2 0 -5 1 ] "modelindices" "int" 2 [ 0 -1 ]
Create "c" "cubiccurves" Connect "c" "" ".root" "objects"
SetAttribute "c" "nvertices" "int" 1 4 "P" "point" 4 [ 0 0 0 1 1 0 2 0 0 3 1 0 ] "basis" "string" 1 "b-spline"
Create "p" "particles" Connect "p" "" ".root" "objects" SetAttribute "p" "P" "point" 1 [ 0 2 -3 ] "width" "float" 1 0.5
Create "glow" "shader" SetAttribute "glow" "shaderfilename" "string" 1 "emitter" "power" "float" 1 10
Create "a" "attributes" Connect "glow" "" "a" "surfaceshader" "priority" "int" 1 2 Connect "a" "" "p" "geometryattributes"
Create "env" "environment" Connect "env" "" ".root" "objects" SetAttribute "env" "angle" "double" 1 5
Delete "xf" "recursive" "int" 1 1
RenderControl "action" "string" 1 "start"
RenderControl "action" "string" 1 "wait"
