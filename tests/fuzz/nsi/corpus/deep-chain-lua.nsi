# A 3,000-deep transform chain made by a script, leaves first and connected
# from the leaf up (past the cycle check's search budget), closed into a
# cycle, then a start: the ordering pass finds and removes that link; the
# recursive delete runs down the whole chain.
Evaluate "type" "string" 1 "lua" "script" "string" 1 "
local n = 3000
for i = n - 1, 0, -1 do nsi.Create('t' .. i, 'transform') end
nsi.Connect('t0', '', '.root', 'objects')
for i = n - 1, 1, -1 do nsi.Connect('t' .. i, '', 't' .. (i - 1), 'objects') end
nsi.Connect('t0', '', 't' .. (n - 1), 'objects')
nsi.Create('m', 'mesh')
nsi.Connect('m', '', 't' .. (n - 1), 'objects')
"
RenderControl "action" "string" 1 "start"
RenderControl "action" "string" 1 "wait"
Delete "t0" "recursive" "int" 1 1
