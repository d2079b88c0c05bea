#version 3.7;
global_settings { assumed_gamma 1.0 }
difference {
  box { <0,0,0>, <10,10,1> }
#for (i, 0, 39)
#for (j, 0, 39)
  cylinder { <(i+0.5)/4, (j+0.5)/4, -1>, <(i+0.5)/4, (j+0.5)/4, 2>, 0.1 }
#end
#end
  pigment { color rgb 0.8 } finish { diffuse 0.8 specular 0.2 }
}
camera { location <9.7, -8.5, 19> look_at <5,5,0.5> sky z angle 40 }
light_source { <0, -8, 30> color rgb 0.9 }
light_source { <9.7, -8.5, 19> color rgb 0.2 }
background { color rgb 0.2 }
