# Floor lit by a hidden quad light, written as a PNG.
Create "cam_xf" "transform"
SetAttribute "cam_xf"
  "transformationmatrix" "doublematrix" 1 [ 1 0 0 0  0 1 0 0  0 0 1 0  0 1 6 1 ]
Connect "cam_xf" "" ".root" "objects"
Create "cam" "perspectivecamera"
SetAttribute "cam"
  "fov" "float" 1 45
Connect "cam" "" "cam_xf" "objects"
Create "scr" "screen"
SetAttribute "scr"
  "resolution" "int[2]" 1 [ 48 36 ]
  "oversampling" "int" 1 8
Connect "scr" "" "cam" "screens"
Create "beauty" "outputlayer"
SetAttribute "beauty"
  "variablename" "string" 1 "Ci"
  "scalarformat" "string" 1 "uint8"
Connect "beauty" "" "scr" "outputlayers"
Create "file" "outputdriver"
SetAttribute "file"
  "drivername" "string" 1 "png"
  "imagefilename" "string" 1 "floor-lamp.png"
Connect "file" "" "beauty" "outputdrivers"
Create "floor" "mesh"
SetAttribute "floor"
  "nvertices" "int" 1 4
  "P" "point" 4 [ -3 0 3  3 0 3  3 0 -3  -3 0 -3 ]
Connect "floor" "" ".root" "objects"
Create "grey" "shader"
SetAttribute "grey"
  "shaderfilename" "string" 1 "${DELIGHT}/osl/dlPrincipled.oso"
  "i_color" "color" 1 [ 0.6 0.6 0.6 ]
Create "floor_attr" "attributes"
Connect "grey" "" "floor_attr" "surfaceshader"
Connect "floor_attr" "" "floor" "geometryattributes"
Create "lamp_xf" "transform"
SetAttribute "lamp_xf"
  "transformationmatrix" "doublematrix" 1 [ 1 0 0 0  0 1 0 0  0 0 1 0  0 3 0 1 ]
Connect "lamp_xf" "" ".root" "objects"
Create "lamp" "mesh"
SetAttribute "lamp"
  "nvertices" "int" 1 4
  "P" "point" 4 [ -0.5 0 -0.5  0.5 0 -0.5  0.5 0 0.5  -0.5 0 0.5 ]
Connect "lamp" "" "lamp_xf" "objects"
Create "glow" "shader"
SetAttribute "glow"
  "shaderfilename" "string" 1 "emitter"
  "power" "float" 1 100
Create "lamp_attr" "attributes"
SetAttribute "lamp_attr"
  "visibility.camera" "int" 1 0
Connect "glow" "" "lamp_attr" "surfaceshader"
Connect "lamp_attr" "" "lamp_xf" "geometryattributes"
RenderControl
  "action" "string" 1 "start"
RenderControl
  "action" "string" 1 "wait"
