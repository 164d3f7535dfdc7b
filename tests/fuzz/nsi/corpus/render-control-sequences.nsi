# Every render control action, in orders that once hung or misbehave: wait
# on a suspended render, suspend before start, synchronize while suspended.
Create "cam" "perspectivecamera"
Connect "cam" "" ".root" "objects"
Create "scr" "screen"
SetAttribute "scr" "resolution" "int[2]" 1 [ 8 8 ] "oversampling" "int" 1 4
Connect "scr" "" "cam" "screens"
RenderControl "action" "string" 1 "suspend"
RenderControl "action" "string" 1 "wait"
RenderControl "action" "string" 1 "start"
RenderControl "action" "string" 1 "suspend"
RenderControl "action" "string" 1 "wait"
RenderControl "action" "string" 1 "synchronize"
RenderControl "action" "string" 1 "wait"
RenderControl "action" "string" 1 "resume"
RenderControl "action" "string" 1 "start" "interactive" "int" 1 1
RenderControl "action" "string" 1 "stop"
RenderControl "action" "string" 1 "resume"
RenderControl "action" "string" 1 "synchronize"
RenderControl "action" "string" 1 "stop"
RenderControl "action" "string" 1 "wait"
