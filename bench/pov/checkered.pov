#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare Small = box { <-.1,-.1,-.1>, <.1,.1,.1> translate <.8,.8,1.1> }
#declare Grid = union { #for (i,0,4) #for (j,0,4) object { Small translate <-0.4*i, -0.4*j, 0> } #end #end }
difference {
  box { <-1.1,-1.1,-1.1>, <1.1,1.1,1.1> }
  object { Grid } object { Grid rotate 90*x } object { Grid rotate 180*x } object { Grid rotate 270*x }
  object { Grid rotate 90*y } object { Grid rotate 270*y }
  pigment { color rgb 0.8 } finish { diffuse 0.8 specular 0.2 }
}
camera { location <4.5, -4.5, 3.6> look_at <0,0,0> sky z angle 40 }
light_source { <2, -4.5, 9> color rgb 0.9 }
light_source { <4.5, -4.5, 3.6> color rgb 0.2 }
background { color rgb 0.2 }
