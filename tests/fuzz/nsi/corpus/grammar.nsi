Create "hair" "curves" SetAttribute "hair" "nvertices" "int" 1 4
  "basis" "string" 1 "b-spline" "extrapolate" "int" 1 1
  "P" "point" 8 [ 0 0 0 0 1 0 0 2 0 0 3 0   1 0 0 1 1 0 1 2 0 1 3 0 ]
  "width" "v float" 8 [ .1 .1 .1 .1 .05 .05 .05 .05 ]   # per vertex
SetAttribute "grid" "st" "float[2]" 4 [ 0 0 1 0 1 1 0 1 ] "st.indices" "int" 4 [ 0 1 2 3 ]
SetAttributeAtTime "xf" -0.25 "transformationmatrix" "doublematrix" 1 [ 1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1 ]
SetAttribute "tag" "label" "string" 2 [ "say \"hi\"" "a\tb\001" ] "none" "int" 0 [ ]
Connect "mirror" "" "ghost" "visibility" "value" "int" 1 1 "priority" "int" 1 2
Connect "tex" "outColor" "surf" "i_color"
Disconnect ".all" "" ".root" "objects"
DeleteAttribute "xf" "transformationmatrix"
Delete "surf" "recursive" "int" 1 1
Evaluate "type" "string" 1 "apistream" "filename" "string" 1 "${ASSETS}/tree.nsi.gz"
Evaluate "type" "string" 1 "lua" "script" "string" 1 "nsi.Create(\"lamp\", \"transform\")"
