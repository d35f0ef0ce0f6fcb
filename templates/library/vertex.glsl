// hexc's pass-through vertex stage (`hexc --vertex`): it feeds every input of a material's fragment shader from a
// vertex attribute of the same type, and takes the clip-space position from attribute 0. codegen writes one
// `varying` section per fragment input (${name}, ${type}, ${location}: the fragment's; ${attribute}: its vertex
// attribute, 1, 2, ... in location order; ${flat}: `flat ` for integer types) and one `copy` each, into `main`.

//@ main
#version 450
layout(location = 0) in vec4 hexc_position;
${varyings}

void main() {
    gl_Position = hexc_position;
${copies}
}

//@ varying
layout(location = ${attribute}) in ${type} hexc_in_${name};
layout(location = ${location}) ${flat}out ${type} ${name};

//@ copy
    ${name} = hexc_in_${name};
