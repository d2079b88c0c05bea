#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare S = 0.989227963463;
#declare Seg = difference { sphere{<0,0,0>,1} sphere{<0,-.02,0>,1 scale S} sphere{<0,.02,0>,1 scale S} translate <3,0,0> }
union {
#for (k, 0, 64)
  object { Seg #for (j, 1, k) rotate 12*z scale 0.979 #end }
#end
  pigment { color rgb 0.8 } finish { diffuse 0.8 specular 0.2 }
}
camera { location <2.5, -8, 9> look_at <0.3,0.2,0> sky z angle 40 }
light_source { <-5, -8, 14> color rgb 0.9 }
light_source { <2.5, -8, 9> color rgb 0.2 }
background { color rgb 0.2 }
